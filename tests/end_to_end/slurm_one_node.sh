# A one-node SLURM cluster on this machine for the tests, sourced by
# workflow_on_slurm.sh: munged, slurmctld and slurmd (Debian's slurm-wlm and
# munge) with their key, sockets, state, logs and slurm.conf in one folder,
# on ports of their own, so nothing of the machine's own configuration is
# read or changed. Needs root (slurmd starts each job as its user).
#   slurm_start DIR CPUS   start it; exports SLURM_CONF; returns 1 with a
#                          reason in SLURM_SKIP when this machine cannot
#   slurm_stop DIR         stop what slurm_start started

slurm_start() {
  local dir=$1 cpus=$2
  SLURM_SKIP=""
  for tool in munged mungekey slurmctld slurmd sbatch sinfo srun scontrol; do
    command -v "$tool" > /dev/null || { SLURM_SKIP="$tool missing (scripts/install-deps.sh installs slurm-wlm and munge)"; return 1; }
  done
  [ "$(id -u)" -eq 0 ] || { SLURM_SKIP="slurmd needs root to start jobs"; return 1; }
  mkdir -p "$dir/munge" "$dir/state" "$dir/spool"
  chmod 700 "$dir/munge"
  mungekey --create --keyfile="$dir/munge/munge.key" 2> "$dir/munge.err" ||
    { SLURM_SKIP="mungekey failed: $(head -c 200 "$dir/munge.err")"; return 1; }
  munged --force --socket="$dir/munge/socket" --key-file="$dir/munge/munge.key" \
    --pid-file="$dir/munge/munged.pid" --log-file="$dir/munge/munged.log" --seed-file="$dir/munge/seed" \
    2>> "$dir/munge.err" || { SLURM_SKIP="munged did not start: $(head -c 200 "$dir/munge.err")"; return 1; }
  # Ports of our own, away from a site's 6817/6818.
  local base=$((20000 + $$ % 20000))
  local node memory
  node=$(hostname -s)
  memory=$(slurmd -C | sed -n 's/.*RealMemory=\([0-9]*\).*/\1/p')
  cat > "$dir/slurm.conf" <<EOF
ClusterName=boxlodtest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$base
SlurmdPort=$((base + 1))
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/socket
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
MpiDefault=none
ReturnToService=2
MinJobAge=3600
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=main Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
  export SLURM_CONF=$dir/slurm.conf
  slurmctld -i 2> "$dir/slurmctld.err" || { SLURM_SKIP="slurmctld did not start: $(head -c 200 "$dir/slurmctld.err")"; return 1; }
  slurmd 2> "$dir/slurmd.err" || { SLURM_SKIP="slurmd did not start: $(head -c 200 "$dir/slurmd.err")"; return 1; }
  for _ in $(seq 60); do
    [ "$(sinfo -h -o %t 2> /dev/null)" = idle ] && return 0
    sleep 1
  done
  SLURM_SKIP="the node did not become idle in 60 s: $(sinfo -h -o '%t %E' 2>&1 | head -c 200); $(tail -n 3 "$dir/slurmd.log" 2> /dev/null)"
  return 1
}

slurm_stop() {
  local dir=$1
  for pid_file in "$dir/slurmd.pid" "$dir/slurmctld.pid" "$dir/munge/munged.pid"; do
    [ -f "$pid_file" ] && kill "$(cat "$pid_file")" 2> /dev/null
  done
  sleep 1
  for pid_file in "$dir/slurmd.pid" "$dir/slurmctld.pid" "$dir/munge/munged.pid"; do
    [ -f "$pid_file" ] && kill -9 "$(cat "$pid_file")" 2> /dev/null
  done
  return 0
}
