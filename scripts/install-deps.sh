#!/usr/bin/env bash
# Installs the Debian packages boxlod needs that are missing; nothing else.
# Usage: scripts/install-deps.sh [demo|bench|fuzz|paper]   (demo: only what `make demo` needs;
# the default, for make test, includes SLURM and munge for the scheduler test;
# bench adds the benchmarks' peers, fuzz clang;
# paper: the workflow, notebooks and LaTeX, which the default list also holds
# because `make test` builds the paper on tiny inputs)
set -euo pipefail

# The boxlod program.
program_packages=(
  build-essential cmake pkg-config
  libeigen3-dev libcgal-dev libtinygltf-dev nlohmann-json3-dev libstb-dev libspng-dev libdeflate-dev
  libopenexr-dev libassimp-dev libmeshoptimizer-dev libsdl2-dev libproj-dev
)
# The tests and benchmarks.
build_packages=("${program_packages[@]}" libgtest-dev libgmock-dev libbenchmark-dev)
# The layout test (tests/end_to_end/formatted.sh): this clang-format exactly, as versions lay out differently.
build_packages+=(clang-format-14)
# Real data for the tests and the demo: the KIT FZK-Haus (IFC) and the assimp CLI that converts it.
data_packages=(assimp-utils assimp-testmodels)
# The SSIM reference test: scikit-image's structural_similarity (reads PNGs through imageio).
data_packages+=(python3-skimage python3-imageio)
# make demo's plot.
data_packages+=(python3-matplotlib)

# The rasterizer benchmark's peer: Mesa's llvmpipe through OSMesa.
bench_packages=(libosmesa6-dev)

# make fuzz: libFuzzer and the sanitizers come with clang.
fuzz_packages=(clang libclang-rt-14-dev)

# The glTF-Validator test runs the Khronos validator (npm gltf-validator) under
# Node.js; the 3D Tiles test loads a city in CesiumJS in headless Chromium.
data_packages+=(nodejs chromium)
command -v npm > /dev/null 2>&1 || data_packages+=(npm)  # (a Node.js from elsewhere may bring its own npm)

# The chain test in Blender (tests/end_to_end/chain_blender.sh): its own glTF importer, run headless.
data_packages+=(blender)

# The viewer's test runs it in a virtual X server.
data_packages+=(xvfb xauth)

# The workflow (Snakemake), the notebooks run headless (Debian's python3 as
# their kernel) and the paper (LaTeX): make paper, and tests/end_to_end/workflow_end_to_end.sh.
paper_packages=(snakemake python3-yaml python3-pandas python3-matplotlib
  python3-nbformat python3-nbclient python3-nbconvert python3-ipykernel
  texlive-latex-base texlive-latex-recommended texlive-fonts-recommended latexmk)

# The workflow on a real scheduler (tests/end_to_end/workflow_on_slurm.sh, make test-cluster):
# a one-node SLURM cluster, its daemons and their authentication.
cluster_packages=(slurmctld slurmd slurm-client munge)

wanted=("${build_packages[@]}" "${data_packages[@]}" "${paper_packages[@]}" "${cluster_packages[@]}")
# make demo: the program, the FZK-Haus and the plot; no tests, benchmarks, viewer test or LaTeX.
# IFC is read by web-ifc under Node.js (toolkit/formats/ifc_io.h), installed below.
program_packages+=(nodejs)
command -v npm > /dev/null 2>&1 || program_packages+=(npm)
[ "${1:-}" = demo ] && wanted=("${program_packages[@]}" assimp-testmodels python3-matplotlib)
[ "${1:-}" = bench ] && wanted+=("${bench_packages[@]}")
[ "${1:-}" = fuzz ] && wanted+=("${fuzz_packages[@]}")

missing=()
for package in "${wanted[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing missing Debian packages: ${missing[*]}" >&2
  if [ "$(id -u)" -eq 0 ]; then
    run=()
  elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    run=(sudo -n)
  else
    echo "install-deps: need root or password-less sudo to install: ${missing[*]}" >&2
    echo "install-deps: run as root: apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  "${run[@]}" apt-get update -qq
  "${run[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

# web-ifc, pinned (toolkit/formats/web_ifc_version.txt), from npm into the
# npm cache folder the program looks in (toolkit/formats/ifc_io.h), never committed.
web_ifc_version=$(cat "$(dirname "$0")/../toolkit/formats/web_ifc_version.txt")
web_ifc=${BOXLOD_NPM_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/boxlod/npm}/web-ifc-$web_ifc_version
if [ ! -f "$web_ifc/node_modules/web-ifc/web-ifc-api-node.js" ]; then
  echo "install-deps: installing web-ifc $web_ifc_version from npm into $web_ifc" >&2
  mkdir -p "$web_ifc"
  npm install --prefix "$web_ifc" --no-audit --no-fund --loglevel=error "web-ifc@$web_ifc_version" >&2
fi
