#!/usr/bin/env bash
# A real Slurm cluster of one node on this machine, for trying facet's farm
# jobs and for the test suite (docs/farm.md, "Try it on a one-host Slurm
# cluster"). Debian's slurm-wlm daemons are started by hand with a
# generated slurm.conf, so no systemd, munge or root-owned /etc files are
# needed, and a system Slurm, if any, is left alone.
#
#   scripts/slurm-cluster.sh start DIR   start it, with its files in DIR; prints
#                                        "export SLURM_CONF=DIR/slurm.conf"
#   scripts/slurm-cluster.sh stop DIR    stop the daemons started for DIR, by
#                                        their process ids (safe to repeat)
set -euo pipefail

usage() {
    echo "usage: $0 start|stop DIR" >&2
    exit 2
}
[ $# -eq 2 ] || usage
action=$1
dir=$2

stop() {
    for daemon in slurmd slurmctld; do
        local pidfile="$dir/$daemon.pid"
        [ -f "$pidfile" ] || continue
        local pid
        pid=$(cat "$pidfile")
        # Only a process that is still that daemon: a pid may be reused.
        if [ -n "$pid" ] && grep -qs "$daemon" "/proc/$pid/comm"; then
            kill "$pid" 2>/dev/null || true
            for _ in $(seq 1 100); do
                grep -qs "$daemon" "/proc/$pid/comm" || break
                sleep 0.1
            done
            if grep -qs "$daemon" "/proc/$pid/comm"; then kill -9 "$pid" 2>/dev/null || true; fi
        fi
        rm -f "$pidfile"
    done
}

# A free TCP port from the kernel, for slurmctld and slurmd: the usual 6817
# and 6818 may belong to a system Slurm.
free_port() {
    python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

start() {
    if ! command -v slurmctld >/dev/null || ! command -v sbatch >/dev/null; then
        echo "slurm-cluster: installing slurm-wlm" >&2
        export DEBIAN_FRONTEND=noninteractive
        apt-get update -qq && apt-get install -y -qq --no-install-recommends slurm-wlm >/dev/null
    fi
    mkdir -p "$dir/state" "$dir/spool"
    dir=$(cd "$dir" && pwd)
    local host cpus memory ctld_port node_port
    host=$(hostname -s)
    cpus=$(nproc)
    memory=$(awk '/MemTotal/ { print int($2 / 1024 * 0.9) }' /proc/meminfo)
    ctld_port=$(free_port)
    node_port=$(free_port)
    while [ "$node_port" = "$ctld_port" ]; do node_port=$(free_port); done
    # Every path under DIR; addresses by number, so the host's name need not
    # resolve; auth/none because the cluster is this host alone
    # and lives as long as one test; kill_invalid_depend so a job whose
    # dependency failed is cancelled instead of waiting forever.
    cat > "$dir/slurm.conf" <<CONF
ClusterName=facet-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$node_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/none
CredType=cred/none
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
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
DependencyParameters=kill_invalid_depend
KillWait=5
MinJobAge=600
SlurmctldTimeout=30
SlurmdTimeout=30
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=main Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
    export SLURM_CONF="$dir/slurm.conf"
    slurmctld -f "$SLURM_CONF" -i
    slurmd -f "$SLURM_CONF"
    for _ in $(seq 1 300); do
        if sinfo -h -o '%T' 2>/dev/null | grep -qx idle; then
            echo "export SLURM_CONF=$dir/slurm.conf"
            return 0
        fi
        sleep 0.2
    done
    echo "slurm-cluster: the node did not become idle in 60 s" >&2
    tail -n 20 "$dir/slurmctld.log" "$dir/slurmd.log" >&2 || true
    stop
    exit 1
}

case "$action" in
start) start ;;
stop) stop ;;
*) usage ;;
esac
