# A single-node Slurm on this machine, for tests: source it, then
#   slurm_start DIR   (munged, slurmctld and slurmd with their state, logs and
#                     sockets under DIR; exports SLURM_CONF; returns 77 when it
#                     cannot: not root, or the packages missing)
#   slurm_stop        (stops all three; the caller traps it on EXIT)
# Process tracking by linuxproc and no task plugin: no cgroups needed.  Ports
# 16817/16818 (not Slurm's defaults, so a real installation is left alone).
# Packages: slurmctld slurmd slurm-client munge (scripts/install-deps.sh).

slurm_start() {
  local d=$1
  if [ "$(id -u)" -ne 0 ]; then echo "local slurm: needs root to start munged/slurmd; skipped"; return 77; fi
  for b in munged slurmctld slurmd sbatch squeue scontrol scancel; do
    command -v "$b" >/dev/null 2>&1 || { echo "local slurm: $b not installed (scripts/install-deps.sh); skipped"; return 77; }
  done
  SLURM_TEST_DIR=$d
  rm -rf "$d"; mkdir -p "$d/state" "$d/spool" "$d/log" "$d/munge"
  chown munge:munge "$d/munge" 2>/dev/null || true
  local key=/etc/munge/munge.key
  if [ ! -s "$key" ]; then dd if=/dev/urandom of="$d/munge.key" bs=1024 count=1 2>/dev/null; key=$d/munge.key; chown munge:munge "$key" 2>/dev/null; chmod 400 "$key"; fi
  munged --socket="$d/munge/munge.sock" --pid-file="$d/munge/munged.pid" --log-file="$d/munge/munged.log" \
         --seed-file="$d/munge/seed" --key-file="$key" -f || { echo "local slurm: munged did not start"; return 1; }
  local host; host=$(hostname -s)
  local mem; mem=$(awk '/MemTotal/ {printf "%d", $2/1024*0.8}' /proc/meminfo)
  local cpus; cpus=$(nproc)
  cat > "$d/slurm.conf" <<CONF
ClusterName=drawbendtest
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$d/munge/munge.sock
CredType=cred/munge
SlurmctldPort=16817
SlurmdPort=16818
StateSaveLocation=$d/state
SlurmdSpoolDir=$d/spool
SlurmctldPidFile=$d/slurmctld.pid
SlurmdPidFile=$d/slurmd.pid
SlurmctldLogFile=$d/log/slurmctld.log
SlurmdLogFile=$d/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SwitchType=switch/none
MpiDefault=none
MinJobAge=600
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
ReturnToService=2
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=local Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF=$d/slurm.conf
  slurmctld -f "$SLURM_CONF" || { echo "local slurm: slurmctld did not start"; cat "$d/log/slurmctld.log"; return 1; }
  slurmd -f "$SLURM_CONF" || { echo "local slurm: slurmd did not start"; cat "$d/log/slurmd.log"; return 1; }
  local i
  for i in $(seq 1 60); do
    if sinfo -h -o %T 2>/dev/null | grep -q idle; then echo "local slurm: up ($host, $cpus CPUs, $mem MB)"; return 0; fi
    sleep 0.5
  done
  echo "local slurm: the node never became idle"; sinfo; tail -20 "$d/log/slurmctld.log" "$d/log/slurmd.log"
  return 1
}

slurm_stop() {
  local d=${SLURM_TEST_DIR:-}
  [ -n "$d" ] || return 0
  local f
  for f in "$d/slurmd.pid" "$d/slurmctld.pid" "$d/munge/munged.pid"; do
    [ -s "$f" ] && kill "$(cat "$f")" 2>/dev/null
  done
  sleep 1
  for f in "$d/slurmd.pid" "$d/slurmctld.pid" "$d/munge/munged.pid"; do
    [ -s "$f" ] && kill -9 "$(cat "$f")" 2>/dev/null
  done
  SLURM_TEST_DIR=
  return 0
}
