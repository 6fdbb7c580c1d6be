#!/usr/bin/env bash
# A real Slurm on this machine, for the farm scripts' tests and for trying them out: munge,
# slurmctld and slurmd from Debian's slurm-wlm and munge packages, run as root from a
# directory of their own, with one node (this machine, all its cores) in one partition.
#
#   tools/farm/local-slurm.sh start DIR   # prints the line to source: export SLURM_CONF=...
#   tools/farm/local-slurm.sh stop DIR    # stops exactly the daemons that start started
#
# Nothing outside DIR is written or read (no /etc/slurm, no /etc/munge, no system munged).
# Ports: PRISM_SLURM_PORT (slurmctld, default 6817) and the next one (slurmd).
set -euo pipefail

usage() {
    echo "usage: $0 start|stop DIR" >&2
    exit 2
}
[[ $# -eq 2 ]] || usage
action=$1
dir=$(realpath -m "$2")

need() {
    for program in "$@"; do
        if ! command -v "$program" >/dev/null && [[ ! -x /usr/sbin/$program ]]; then
            echo "local-slurm: $program is missing: install Debian's slurm-wlm and munge" \
                 "(tools/scripts/install-deps.sh does)" >&2
            exit 1
        fi
    done
}

# Kills the process whose pid `file` holds, if it is still running, and waits for it.
stop_pid() {
    local file=$1
    [[ -f $file ]] || return 0
    local pid
    pid=$(cat "$file")
    if kill -0 "$pid" 2>/dev/null; then
        kill "$pid" 2>/dev/null || true
        for _ in $(seq 50); do
            kill -0 "$pid" 2>/dev/null || break
            sleep 0.1
        done
        kill -9 "$pid" 2>/dev/null || true
    fi
    rm -f "$file"
}

case $action in
start)
    need munged mungekey slurmctld slurmd sinfo
    if [[ $(id -u) -ne 0 ]]; then
        echo "local-slurm: run as root (the daemons run as root here)" >&2
        exit 1
    fi
    if [[ -f $dir/slurmctld.pid ]] && kill -0 "$(cat "$dir/slurmctld.pid")" 2>/dev/null; then
        echo "local-slurm: a Slurm started from $dir is running already; stop it first" >&2
        exit 1
    fi
    mkdir -p "$dir"/{munge,state,spool,log}
    chmod 700 "$dir/munge"
    port=${PRISM_SLURM_PORT:-6817}
    host=$(hostname -s)
    cpus=$(nproc)
    # munge: a fresh key, its own socket; --force because root runs it.
    [[ -f $dir/munge/munge.key ]] || /usr/sbin/mungekey --create --keyfile="$dir/munge/munge.key"
    chmod 600 "$dir/munge/munge.key"
    /usr/sbin/munged --force --key-file="$dir/munge/munge.key" \
        --socket="$dir/munge/munge.socket" --pid-file="$dir/munge.pid" \
        --log-file="$dir/log/munged.log" --seed-file="$dir/munge/munge.seed"
    cat >"$dir/slurm.conf" <<CONF
# Written by tools/farm/local-slurm.sh: one node, this machine.
ClusterName=prismlocal
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
# verbose: the log also says what slurmd does before a task starts (a login environment read
# for it, _get_user_env, which tests/farm checks that prism-farm never asks for).
SlurmdDebug=verbose
# No cgroups here: processes are tracked through /proc, tasks are not confined.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
# A job's tasks get a moment to clean up after scancel (prism-render leaves no partial file).
KillWait=5
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=local Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
    export SLURM_CONF=$dir/slurm.conf
    /usr/sbin/slurmctld -i
    /usr/sbin/slurmd
    # Ready when the node is idle.
    for _ in $(seq 100); do
        if [[ $(sinfo -h -N -o %t 2>/dev/null) == idle ]]; then
            echo "export SLURM_CONF=$dir/slurm.conf"
            exit 0
        fi
        sleep 0.2
    done
    echo "local-slurm: the node did not come up in 20 s; logs in $dir/log:" >&2
    tail -n 20 "$dir"/log/*.log >&2 || true
    exit 1
    ;;
stop)
    stop_pid "$dir/slurmd.pid"
    stop_pid "$dir/slurmctld.pid"
    stop_pid "$dir/munge.pid"
    ;;
*)
    usage
    ;;
esac
