# Sourced by the tests that open boxlod's outputs in real web clients
# (tiles_clients.sh, chain_clients.sh): npm packages pinned and installed into
# a cache folder on first use, never committed; pages served on localhost;
# tests/end_to_end/browser_page.mjs drives Debian's headless Chromium.

# npm_client NAME PACKAGE@VERSION...: installs the packages once into the
# cache folder NAME and sets $client to it.
npm_client() {
  local name=$1; shift
  client=${BOXLOD_NPM_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/boxlod/npm}/$name
  if [ ! -f "$client/installed" ]; then
    mkdir -p "$client"
    if ! npm install --prefix "$client" --no-audit --no-fund --loglevel=error "$@" >&2; then
      echo "$name: cannot install $* from the npm registry" >&2
      exit 1
    fi
    touch "$client/installed"
  fi
}

# serve FOLDER: serves it on a free localhost port, sets $port and $server
# (the caller kills $server on exit), and waits until it answers.
serve() {
  port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
  /usr/bin/python3 -m http.server "$port" --bind 127.0.0.1 --directory "$1" > /dev/null 2>&1 &
  server=$!
  for _ in $(seq 50); do
    /usr/bin/python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/')" 2>/dev/null && return
    sleep 0.2
  done
}

# open_page URL RESULT.json SCREENSHOT.png: the page's window.result.
open_page() {
  node "$(dirname "${BASH_SOURCE[0]}")/browser_page.mjs" "$client/node_modules/playwright-core" "$1" "$3" > "$2"
}
