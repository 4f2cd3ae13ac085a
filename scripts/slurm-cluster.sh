#!/usr/bin/env bash
# A real Slurm cluster of one node on this machine, for trying facet's farm
# jobs and for the test suite (docs/farm.md, "Try it on a one-host Slurm
# cluster"). Debian's slurm-wlm daemons are started by hand with a
# generated slurm.conf, so neither systemd nor root-owned files in /etc or
# /run are needed, and a system Slurm, if any, is left alone: its own ports,
# state, logs and pid files all live in DIR.
#
#   scripts/slurm-cluster.sh start DIR   start it, with its files in DIR; prints
#                                        "export SLURM_CONF=DIR/slurm.conf"
#                                        (and nothing else) on standard output
#   scripts/slurm-cluster.sh stop DIR    cancel its jobs and stop the daemons
#                                        started for DIR, by their process ids;
#                                        safe to repeat
#
# Typical use:  eval "$(scripts/slurm-cluster.sh start "$dir")"
#               trap 'scripts/slurm-cluster.sh stop "$dir"' EXIT
#
# SLURM_CLUSTER_AUTH=munge forces munge authentication (with a munged of
# its own in DIR) even where Slurm has auth/none; the default is auth/none
# when the plugin exists, munge otherwise.
set -Eeuo pipefail

usage() {
    echo "usage: $0 start|stop DIR" >&2
    exit 2
}
[ $# -eq 2 ] || usage
action=$1
dir=$2

log() {
    echo "slurm-cluster: $*" >&2
}

# "NAME PID" a line for each daemon started, written as each one starts, so
# that stop ends exactly those and nothing else.
pids_file() {
    echo "$dir/daemons.pids"
}

# Whether PID is still the daemon NAME that was started for DIR: a process
# id may have been reused since, and a system daemon of the same name must
# be left alone. Every daemon started here names DIR on its command line.
is_ours() {
    local name=$1 pid=$2
    [ -n "$pid" ] && alive "$pid" || return 1
    [ "$(cat "/proc/$pid/comm" 2>/dev/null)" = "$name" ] || return 1
    # 2>/dev/null before the redirection, which reports its own error (the
    # process may end meanwhile) to the stderr in force when it is made.
    tr '\0' ' ' 2>/dev/null < "/proc/$pid/cmdline" | grep -qF -- "$dir/"
}

# Whether process $1 runs. A zombie has ended: the daemons are reparented
# to PID 1, and in a container that may be slow to reap them, or never.
alive() {
    local state
    state=$(awk '/^State:/ { print $2 }' 2>/dev/null < "/proc/$1/status") || return 1
    [ -n "$state" ] && [ "$state" != Z ]
}

# Waits up to $2 seconds for process $1 to exit; fails if it did not.
wait_exit() {
    local pid=$1 deadline=$((SECONDS + $2))
    while alive "$pid" && [ "$SECONDS" -lt "$deadline" ]; do sleep 0.1; done
    ! alive "$pid"
}

# The slurmstepd processes (one for each job step, with the job's
# processes under it) of this cluster. slurmd starts them as daemons of
# their own, so they are not its children; they are known by SLURM_CONF in
# the environment they inherit from slurmd, which start set to DIR's.
stepds() {
    local pid
    for pid in $(pgrep -x slurmstepd 2>/dev/null || true); do
        if tr '\0' '\n' 2>/dev/null < "/proc/$pid/environ" | grep -qxF "SLURM_CONF=$dir/slurm.conf"; then
            echo "$pid"
        fi
    done
}

# The process ids under process $1, all generations.
descendants() {
    local child
    for child in $(pgrep -P "$1" 2>/dev/null || true); do
        echo "$child"
        descendants "$child"
    done
}

stop() {
    [ -d "$dir" ] || return 0
    dir=$(cd "$dir" && pwd)
    local pidsf name pid left=""
    pidsf=$(pids_file)
    [ -f "$pidsf" ] || return 0

    # Jobs first: slurmstepd and the job's processes would outlive slurmd.
    # scancel needs the controller; a dead one is not waited for.
    while read -r name pid; do
        if [ "$name" = slurmctld ] && is_ours slurmctld "$pid"; then
            local jobs
            jobs=$(SLURM_CONF="$dir/slurm.conf" timeout 10 squeue -h -o %A 2>/dev/null < /dev/null || true)
            if [ -n "$jobs" ]; then
                # shellcheck disable=SC2086 # one argument per job id
                SLURM_CONF="$dir/slurm.conf" timeout 10 scancel $jobs 2>/dev/null < /dev/null || true
            fi
        fi
    done < "$pidsf"
    # KillWait (5 s) after SIGTERM, a job's processes get SIGKILL.
    local deadline=$((SECONDS + 15))
    while [ -n "$(stepds)" ] && [ "$SECONDS" -lt "$deadline" ]; do sleep 0.2; done

    # The daemons in the reverse order of their start: slurmd, slurmctld,
    # then munged, which both use to the end.
    local order
    order=$(tac "$pidsf")
    while read -r name pid; do
        [ -n "$name" ] || continue
        if is_ours "$name" "$pid"; then
            kill -TERM "$pid" 2>/dev/null || true
            if ! wait_exit "$pid" 15; then
                log "$name ($pid) ignored SIGTERM; killing it"
                kill -KILL "$pid" 2>/dev/null || true
                wait_exit "$pid" 5 || { log "$name ($pid) is still running"; left=1; }
            fi
        fi
    done <<< "$order"

    # A step whose slurmd died first is left to itself: end it, and the
    # job's processes under it, which would otherwise outlive it.
    local tree
    for pid in $(stepds); do
        tree=$(descendants "$pid")
        # shellcheck disable=SC2086 # one argument per process id
        kill -KILL "$pid" $tree 2>/dev/null || true
        wait_exit "$pid" 5 || { log "slurmstepd ($pid) is still running"; left=1; }
    done
    # The record stays while anything in it may still run, for another try.
    if [ -n "$left" ]; then return 1; fi
    rm -f "$pidsf"
}

# A TCP port nothing on this machine uses, below the kernel's range for
# outgoing connections so that none takes it before the daemon binds it.
# Slurm's usual 6817 and 6818 may belong to a system Slurm.
free_port() {
    local used low port
    used=$(cat /proc/net/tcp /proc/net/tcp6 2>/dev/null |
        awk 'NR > 1 && $2 ~ /:/ { sub(/.*:/, "", $2); print $2 }' | sort -u)
    read -r low _ < /proc/sys/net/ipv4/ip_local_port_range || low=32768
    [ "$low" -gt 12000 ] || low=32768
    while :; do
        port=$((low - 10000 + RANDOM % 9000))
        # /proc/net/tcp lists ports in hexadecimal, upper case.
        if ! grep -qx "$(printf '%04X' "$port")" <<< "$used"; then
            echo "$port"
            return
        fi
    done
}

install_slurm() {
    if command -v slurmctld >/dev/null && command -v slurmd >/dev/null && command -v sbatch >/dev/null; then
        return 0
    fi
    [ "$(id -u)" -eq 0 ] || { log "slurm-wlm is not installed and only root can install it"; return 1; }
    log "installing slurm-wlm (log: $dir/apt.log)"
    export DEBIAN_FRONTEND=noninteractive
    # The maintainer scripts start each daemon through invoke-rc.d (or
    # deb-systemd-invoke) unless policy-rc.d answers 101. Without one,
    # munge's would leave a system munged running (slurmctld's and slurmd's
    # do nothing without /etc/slurm/slurm.conf). Container images often have
    # such a policy-rc.d already; otherwise one is put there for the install.
    local policy=/usr/sbin/policy-rc.d added="" code=0
    if [ ! -e "$policy" ]; then
        printf '#!/bin/sh\n# slurm-cluster.sh: start no daemon while it installs slurm-wlm\nexit 101\n' > "$policy"
        chmod 755 "$policy"
        added=1
    fi
    { apt-get update -q && apt-get install -y -q --no-install-recommends slurm-wlm; } > "$dir/apt.log" 2>&1 || code=$?
    [ -z "$added" ] || rm -f "$policy"
    if [ "$code" -ne 0 ]; then
        tail -n 20 "$dir/apt.log" >&2
        log "apt-get failed ($code)"
        return 1
    fi
}

# Prints the logs and stops what was started, for a start that failed.
abort() {
    trap - ERR
    log "$*"
    local f
    for f in "$dir"/*.log; do
        if [ ! -f "$f" ] || [ "$f" = "$dir/apt.log" ]; then continue; fi
        echo "--- $f" >&2
        tail -n 30 "$f" >&2
    done
    stop || true
    exit 1
}

# Waits for daemon NAME to write its pid file and records its pid.
record_pid() {
    local name=$1 file=$2 pid="" deadline=$((SECONDS + 15))
    while [ "$SECONDS" -lt "$deadline" ]; do
        pid=$(cat "$file" 2>/dev/null || true)
        if is_ours "$name" "$pid"; then
            echo "$name $pid" >> "$(pids_file)"
            return 0
        fi
        sleep 0.1
    done
    abort "$name did not start (no live process in $file)"
}

start_munged() {
    local m="$dir/munge"
    # munged refuses a key or socket folder that others could write to.
    mkdir -p "$m"
    chmod 700 "$m"
    mungekey --create --keyfile="$m/munge.key" 2>/dev/null ||
        dd if=/dev/urandom of="$m/munge.key" bs=1024 count=1 status=none
    chmod 400 "$m/munge.key"
    # --force: munged as root only warns then, instead of refusing.
    munged --force --socket="$m/munge.socket" --key-file="$m/munge.key" \
        --pid-file="$m/munged.pid" --log-file="$dir/munged.log" \
        --seed-file="$m/munged.seed" ||
        abort "munged failed to start"
    record_pid munged "$m/munged.pid"
}

start() {
    case "$dir" in
    *[[:space:]]*) log "DIR must not contain white space (slurm.conf cannot quote it)"; exit 2 ;;
    esac
    mkdir -p "$dir"
    dir=$(cd "$dir" && pwd)
    if [ -s "$(pids_file)" ]; then
        local name pid
        while read -r name pid; do
            if is_ours "$name" "$pid"; then log "a cluster is already running in $dir: stop it first"; exit 1; fi
        done < "$(pids_file)"
    fi
    trap 'abort "line $LINENO: a command failed"' ERR
    install_slurm || abort "slurm-wlm could not be installed"
    mkdir -p "$dir/state" "$dir/spool"
    : > "$(pids_file)"

    local host cpus memory ctld_port node_port auth
    # slurmctld and slurmd each find themselves in slurm.conf by the host's
    # short name. Every address is 127.0.0.1, so that name need not resolve.
    host=$(hostname -s 2>/dev/null || uname -n)
    host=${host%%.*}
    cpus=$(nproc)
    # A little under the machine's memory: slurmd drains a node that claims
    # more than it has.
    memory=$(awk '/^MemTotal:/ { print int($2 / 1024 * 0.9) }' /proc/meminfo)
    ctld_port=$(free_port)
    node_port=$(free_port)
    while [ "$node_port" = "$ctld_port" ]; do node_port=$(free_port); done

    # auth/none (Slurm 22.05 still has it; 23.11 dropped it) needs no munge:
    # the cluster is this host alone and lives as long as one test.
    auth=${SLURM_CLUSTER_AUTH:-}
    if [ -z "$auth" ]; then
        if compgen -G '/usr/lib/*/slurm-wlm/auth_none.so' >/dev/null ||
            compgen -G '/usr/lib*/slurm/auth_none.so' >/dev/null; then
            auth=none
        else
            auth=munge
        fi
    fi
    local auth_lines
    case "$auth" in
    none) auth_lines="AuthType=auth/none
CredType=cred/none" ;;
    munge) auth_lines="AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket" ;;
    *) abort "SLURM_CLUSTER_AUTH must be none or munge, not $auth" ;;
    esac

    # Why the less obvious settings:
    #  - proctrack/linuxproc, task/none, jobacct_gather/none: no cgroups, so
    #    it runs in containers without a writable cgroup tree;
    #  - CR_CPU rather than CR_Core: with hyperthreads a core holds two CPUs
    #    and CR_Core would run one 1-CPU job per core, not per CPU;
    #  - config_overrides: slurmd takes CPUs and RealMemory from here rather
    #    than draining the node if its own count (in a container) differs;
    #  - ReturnToService=2: the node comes back by itself after a restart;
    #  - kill_invalid_depend: a job whose dependency can never be met (a
    #    failed afterok) is cancelled instead of pending forever;
    #  - KillWait=5: a cancelled job's processes get SIGKILL 5 s after
    #    SIGTERM, so that stop is quick;
    #  - MinJobAge=600: finished jobs stay visible to squeue and scontrol
    #    for 10 minutes (there is no accounting database for sacct);
    #  - MailProg: slurmctld logs an error without /usr/bin/mail.
    cat > "$dir/slurm.conf" <<CONF
# Generated by scripts/slurm-cluster.sh for a one-host test cluster.
ClusterName=facet-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$node_port
SlurmUser=root
SlurmdUser=root
$auth_lines
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
SelectTypeParameters=CR_CPU
SlurmdParameters=config_overrides
MpiDefault=none
ReturnToService=2
DependencyParameters=kill_invalid_depend
KillWait=5
MinJobAge=600
MailProg=/bin/true
SlurmctldTimeout=30
SlurmdTimeout=30
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=main Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
    # The clients run here (sinfo below) and the daemons' job steps inherit
    # it, which is how stop tells this cluster's slurmstepd processes apart.
    export SLURM_CONF="$dir/slurm.conf"

    [ "$auth" != munge ] || start_munged
    # Both daemons fork into the background and write their pid files;
    # they fail here only for errors found before that (the logs say more).
    # -i: start even though the empty state folder has no saved state.
    slurmctld -i -f "$SLURM_CONF" || abort "slurmctld failed to start"
    record_pid slurmctld "$dir/slurmctld.pid"
    slurmd -f "$SLURM_CONF" -N "$host" || abort "slurmd failed to start"
    record_pid slurmd "$dir/slurmd.pid"

    # Ready once the node has registered and is idle.
    local state="" deadline=$((SECONDS + 60))
    while [ "$SECONDS" -lt "$deadline" ]; do
        state=$(timeout 5 sinfo -h -n "$host" -o '%T %E' 2>/dev/null || true)
        [ "${state%% *}" != idle ] || break
        sleep 0.2
    done
    [ "${state%% *}" = idle ] || abort "the node is not idle after 60 s (sinfo: ${state:-no answer})"
    trap - ERR
    printf 'export SLURM_CONF=%q\n' "$dir/slurm.conf"
}

case "$action" in
start) start ;;
stop) stop ;;
*) usage ;;
esac
