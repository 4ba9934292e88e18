#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, to try scripts/slurm_batch.sh for real (not part of
# CI). Needs root. Installs Debian's slurm-wlm and munge when missing, writes a minimal
# /etc/slurm/slurm.conf for this host (all its cores, no cgroups: works in a container), and
# starts munged, slurmctld and slurmd.
#   scripts/slurm_local.sh          start (again: restarts the daemons)
#   scripts/slurm_local.sh stop     stop the daemons
set -euo pipefail
pidfiles=(/run/slurmctld.pid /run/slurmd.pid /run/munge/munged.pid)
stop() {
  for f in "${pidfiles[@]}"; do
    local pid
    pid="$(cat "$f" 2>/dev/null || true)"
    if [[ -n "$pid" ]] && kill "$pid" 2>/dev/null; then
      for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    fi
    rm -f "$f"
  done
}
if [[ "${1:-}" == stop ]]; then stop; exit 0; fi
[[ "$(id -u)" -eq 0 ]] || { echo "slurm_local.sh: run as root" >&2; exit 1; }
missing=()
for p in slurm-wlm munge; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if (( ${#missing[@]} )); then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
stop

host="$(hostname -s)"
cpus="$(nproc)"
memory_mb=$(( $(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 - 512 ))
mkdir -p /etc/slurm /var/spool/slurmctld /var/spool/slurmd /var/log/slurm /run/munge
chown slurm: /var/spool/slurmctld /var/log/slurm 2>/dev/null || true
cat >/etc/slurm/slurm.conf <<CONF
ClusterName=segmat-local
SlurmctldHost=$host
SlurmUser=root
AuthType=auth/munge
StateSaveLocation=/var/spool/slurmctld
SlurmdSpoolDir=/var/spool/slurmd
SlurmctldPidFile=/run/slurmctld.pid
SlurmdPidFile=/run/slurmd.pid
SlurmctldLogFile=/var/log/slurm/slurmctld.log
SlurmdLogFile=/var/log/slurm/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
NodeName=$host CPUs=$cpus RealMemory=$memory_mb State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF

# munge: a key, then the daemon (as root: no munge user needed inside a container).
[[ -s /etc/munge/munge.key ]] || { mkdir -p /etc/munge; dd if=/dev/urandom bs=1 count=1024 \
  of=/etc/munge/munge.key 2>/dev/null; }
chmod 400 /etc/munge/munge.key
chown root: /etc/munge/munge.key /run/munge /var/lib/munge /var/log/munge 2>/dev/null || true
munged --force --pid-file=/run/munge/munged.pid
slurmctld
slurmd
for _ in $(seq 100); do
  sinfo -h -o %T 2>/dev/null | grep -q -E "idle|mixed" && break
  sleep 0.2
done
sinfo
