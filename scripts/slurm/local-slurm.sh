#!/usr/bin/env bash
# local-slurm.sh -- start/stop a throw-away, single-node, localhost-only Slurm
# cluster (munged + slurmctld + slurmd) for integration tests.
#
# Usage as a library (bash):
#     source /path/to/local-slurm.sh
#     slurm_check                    # the commands are there (scripts/install-deps.sh)
#     dir=$(mktemp -d)
#     trap 'slurm_down; rm -rf "$dir"' EXIT
#     slurm_up "$dir"                # exports SLURM_CONF=$dir/slurm.conf
#     id=$(sbatch --parsable ...)
#     slurm_wait_jobs "$id"          # 0 iff every job (and array task) COMPLETED
#     slurm_down                     # or slurm_down "$dir"; safe to call twice
#
# Usage as a command (e.g. from a Rust test via std::process::Command):
#     local-slurm.sh check
#     local-slurm.sh up   DIR        # daemons keep running after it returns
#     local-slurm.sh wait DIR JOBID...
#     local-slurm.sh down DIR
#   Then run sbatch/squeue/scontrol with SLURM_CONF=DIR/slurm.conf.
#
# Everything the cluster writes lives under DIR (config, munge key/socket,
# state, spool, logs, pid files). Nothing is written to /etc or /var.
#
# Tunables (environment):
#   LOCAL_SLURM_START_TIMEOUT  seconds to wait for the node to become idle (30)
#   LOCAL_SLURM_WAIT_TIMEOUT   default timeout of slurm_wait_jobs, seconds (120)
#   LOCAL_SLURM_CPUS           CPUs= of the node (default: nproc). May exceed the
#                              real count (SlurmdParameters=config_overrides), so
#                              more 1-CPU jobs run at once (fewer ~1 s sched rounds)
#   LOCAL_SLURM_QUIET=1        silence progress messages on stderr

# The library must not change the caller's shell options: no `set -e` here.

_ls_log() { [[ ${LOCAL_SLURM_QUIET:-0} == 1 ]] || printf 'local-slurm: %s\n' "$*" >&2; }
_ls_err() { printf 'local-slurm: ERROR: %s\n' "$*" >&2; }

# Directory of the currently running cluster in this shell (set by slurm_up).
LOCAL_SLURM_DIR=${LOCAL_SLURM_DIR:-}

# ---------------------------------------------------------------------------
# slurm_check: every command the cluster needs is there (scripts/install-deps.sh
# installs the packages; this script installs nothing).
# ---------------------------------------------------------------------------
slurm_check() {
    local missing=() c
    for c in slurmctld slurmd sbatch squeue scontrol sinfo munged ss unshare; do
        # /usr/sbin may be missing from PATH for non-login shells
        if ! command -v "$c" >/dev/null 2>&1 && [[ ! -x /usr/sbin/$c ]]; then
            missing+=("$c")
        fi
    done
    if ((${#missing[@]} > 0)); then
        _ls_err "missing ${missing[*]}: run scripts/install-deps.sh"
        return 1
    fi
}

# ---------------------------------------------------------------------------
# helpers
# ---------------------------------------------------------------------------
_ls_port_free() { # PORT -> 0 if nobody listens on it (tcp, any address)
    [[ -z $(ss -Hltn "sport = :$1" 2>/dev/null) ]]
}

_ls_pick_ports() { # N -> prints N distinct free ports in 17000-18999
    local n=$1 out=() p tries=0
    while ((${#out[@]} < n)); do
        ((tries++ > 500)) && { _ls_err "no free port found in 17000-18999"; return 1; }
        p=$((17000 + (RANDOM % 2000)))
        [[ " ${out[*]} " == *" $p "* ]] && continue
        _ls_port_free "$p" && out+=("$p")
    done
    echo "${out[@]}"
}

_ls_running() { # PID -> 0 if the process exists and is not a zombie
    local stat rest
    [[ $1 =~ ^[0-9]+$ ]] || return 1
    read -r stat 2>/dev/null <"/proc/$1/stat" || return 1
    rest=${stat##*) }
    [[ ${rest:0:1} != Z ]]
}

_ls_alive() { # PID EXPECTED_COMM -> 0 if PID is running and is that program
    local comm
    _ls_running "$1" || return 1
    read -r comm 2>/dev/null <"/proc/$1/comm" || return 1
    [[ $comm == "$2" ]]
}

# Print every PID that belongs to the cluster in DIR: processes carrying the
# marker LOCAL_SLURM_TAG=DIR in their environment (munged, slurmctld, slurmd,
# slurmstepd, as they inherit it) plus all their descendants (job scripts).
# Uses only bash builtins per process (no fork per /proc entry).
_ls_cluster_pids() {
    local tag="LOCAL_SLURM_TAG=$1" p stat rest changed e
    local -a envv fields
    local -A mine=() parent=()
    for p in /proc/[0-9]*; do
        p=${p#/proc/}
        ((p == $$ || p == BASHPID)) && continue
        read -r stat 2>/dev/null <"/proc/$p/stat" || continue
        rest=${stat##*) }           # strip "pid (comm) "
        read -r -a fields <<<"$rest" # fields[0]=state fields[1]=ppid
        parent[$p]=${fields[1]}
        envv=()
        mapfile -d '' envv 2>/dev/null <"/proc/$p/environ" || continue
        for e in "${envv[@]}"; do
            if [[ $e == "$tag" ]]; then mine[$p]=1; break; fi
        done
    done
    # add descendants (fixed point)
    changed=1
    while ((changed)); do
        changed=0
        for p in "${!parent[@]}"; do
            [[ -n ${mine[$p]:-} ]] && continue
            if [[ -n ${mine[${parent[$p]}]:-} ]]; then
                mine[$p]=1
                changed=1
            fi
        done
    done
    ((${#mine[@]})) && printf '%s\n' "${!mine[@]}"
    return 0
}

# _ls_spawn DIR NAME CMD... : start CMD in the background, detached from the
# calling shell (double fork: it is re-parented to PID 1, so a caller's bare
# `wait` never blocks on it and no job-control messages appear), with stdio on
# files under DIR/log (never the caller's pipes: a test harness capturing our
# output would otherwise wait for EOF forever). Its PID goes to
# DIR/run/NAME.pid.sh. LOCAL_SLURM_TAG=DIR in its environment marks it (and
# slurmstepd, which inherits it) as part of this cluster for slurm_down.
_ls_spawn() {
    local dir=$1 name=$2
    shift 2
    (
        LOCAL_SLURM_TAG=$dir "$@" </dev/null >>"$dir/log/$name.stdio" 2>&1 &
        echo $! >"$dir/run/$name.pid.sh"
    )
}

_ls_tail_logs() { # DIR
    local f
    for f in "$1"/log/*.log "$1"/log/*.stdio; do
        [[ -s $f ]] || continue
        printf -- '--- last lines of %s ---\n' "$f" >&2
        tail -n 15 "$f" >&2
    done
}

# ---------------------------------------------------------------------------
# slurm_up DIR
# ---------------------------------------------------------------------------
slurm_up() {
    local -; set +e # immune to the caller's errexit; options restored on return
    local attempt rc
    for attempt in 1 2 3; do
        _ls_up_once "$@"
        rc=$?
        # 3 = a daemon lost a race for its port (parallel slurm_up): retry
        ((rc == 3)) || return "$rc"
        _ls_log "port clash, retrying with other ports (attempt $attempt)"
    done
    return 1
}

_ls_up_once() {
    local dir=${1:?usage: slurm_up DIR}
    local t0=$SECONDS
    mkdir -p "$dir" || return 1
    dir=$(cd "$dir" && pwd -P) || return 1
    # Unix socket paths are limited to 108 bytes: DIR/munge.socket and
    # slurmstepd's DIR/spool/localhost_<jobid>.<stepid> must fit.
    if ((${#dir} > 64)); then
        _ls_err "DIR path too long (${#dir} > 64 chars, Unix socket limit): $dir -- use e.g. mktemp -d"
        return 1
    fi

    # Idempotent: already running for this DIR?
    if _ls_alive "$(cat "$dir/run/slurmctld.pid.sh" 2>/dev/null)" slurmctld &&
        _ls_alive "$(cat "$dir/run/slurmd.pid.sh" 2>/dev/null)" slurmd; then
        export SLURM_CONF="$dir/slurm.conf"
        LOCAL_SLURM_DIR=$dir
        _ls_log "cluster in $dir already running"
        return 0
    fi

    local c
    for c in munged slurmctld slurmd sinfo scontrol ss unshare; do
        command -v "$c" >/dev/null 2>&1 || {
            _ls_err "$c not found in PATH (run scripts/install-deps.sh; is /usr/sbin in PATH?)"
            return 1
        }
    done
    ((EUID == 0)) || { _ls_err "slurm_up must run as root (SlurmUser=root, unshare --uts)"; return 1; }

    LOCAL_SLURM_DIR=$dir
    chmod go-w "$dir" # munged refuses group/world-writable socket dirs
    mkdir -p "$dir"/{munge,state,spool,log,run} || return 1
    chmod 700 "$dir/munge"

    # ---- munge ------------------------------------------------------------
    local key=$dir/munge/munge.key sock=$dir/munge.socket
    if [[ ! -s $key ]]; then
        (umask 077 && dd if=/dev/urandom of="$key" bs=1 count=1024 status=none) || return 1
    fi
    chmod 400 "$key"
    rm -f "$sock" "$sock.lock"

    _ls_spawn "$dir" munged munged -F --force \
        --key-file="$key" --socket="$sock" --pid-file="$dir/run/munged.pid" \
        --log-file="$dir/log/munged.log" --seed-file="$dir/munge/munge.seed"

    # ---- slurm.conf -------------------------------------------------------
    local ports ctld_port slurmd_port ncpu mem
    ports=$(_ls_pick_ports 2) || { slurm_down "$dir"; return 1; }
    read -r ctld_port slurmd_port <<<"$ports"
    ncpu=${LOCAL_SLURM_CPUS:-$(nproc)}
    mem=$(awk '/^MemTotal:/ {m=int($2/1024/2); if (m > 1024) m = 1024; if (m < 100) m = 100; print m}' /proc/meminfo)

    cat >"$dir/slurm.conf" <<EOF
# generated by local-slurm.sh -- localhost-only test cluster
ClusterName=localtest
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
# bind to the address the hostname resolves to (localhost -> 127.0.0.1)
# instead of INADDR_ANY
CommunicationParameters=NoCtldInAddrAny,NoInAddrAny
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$sock
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/run/slurmctld.pid
SlurmdPidFile=$dir/run/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
PlugStackConfig=$dir/plugstack.conf
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
MailProg=/bin/true
SwitchType=switch/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerParameters=batch_sched_delay=0
DependencyParameters=kill_invalid_depend
SlurmdParameters=config_overrides
ReturnToService=2
# keep finished jobs visible to 'scontrol show job' for 10 minutes
MinJobAge=600
SlurmdTimeout=60
InactiveLimit=0
KillWait=2
MessageTimeout=10
TmpFS=/tmp
NodeName=localhost NodeAddr=127.0.0.1 NodeHostname=localhost CPUs=$ncpu RealMemory=$mem State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
    : >"$dir/plugstack.conf"
    export SLURM_CONF="$dir/slurm.conf"

    # wait for the munge socket
    local i
    for ((i = 0; i < 100; i++)); do
        [[ -S $sock ]] && break
        _ls_alive "$(cat "$dir/run/munged.pid.sh")" munged || break
        sleep 0.05
    done
    if [[ ! -S $sock ]]; then
        _ls_err "munged did not start (socket $sock missing)"
        _ls_tail_logs "$dir"; cat "$dir/log/munged.stdio" >&2 2>/dev/null
        slurm_down "$dir"
        return 1
    fi

    # ---- slurmctld / slurmd, each in its own UTS namespace ----------------
    # `unshare` and `sh` both exec, so the recorded PID is the daemon's PID.
    # shellcheck disable=SC2016 # $1 is expanded by the inner sh
    _ls_spawn "$dir" slurmctld unshare --uts -- sh -c \
        'hostname localhost && exec slurmctld -D -c -i -f "$1"' sh "$SLURM_CONF"
    # shellcheck disable=SC2016
    _ls_spawn "$dir" slurmd unshare --uts -- sh -c \
        'hostname localhost && exec slurmd -D -N localhost -f "$1"' sh "$SLURM_CONF"

    # ---- wait for the node to become idle ---------------------------------
    local timeout=${LOCAL_SLURM_START_TIMEOUT:-30} start=$SECONDS state="" d
    while :; do
        # `timeout`: a client retries a dead controller for ~10 s
        state=$(timeout 1 sinfo -h -n localhost -o '%T' 2>/dev/null)
        [[ $state == idle ]] && break
        for d in slurmctld slurmd munged; do
            # the pid may still be `unshare`/`sh` for a few ms before exec
            if ! _ls_running "$(cat "$dir/run/$d.pid.sh")"; then
                slurm_down "$dir"
                if grep -qs 'Address already in use' "$dir/log/$d.stdio"; then
                    : >"$dir/log/$d.stdio"
                    return 3
                fi
                _ls_err "$d exited during start-up"
                _ls_tail_logs "$dir"
                return 1
            fi
        done
        if ((SECONDS - start >= timeout)); then
            _ls_err "node not idle after ${timeout}s (sinfo state: '${state:-none}')"
            scontrol ping >&2 2>&1
            _ls_tail_logs "$dir"
            slurm_down "$dir"
            return 1
        fi
        sleep 0.1
    done

    # ---- verify PIDs and loopback-only listening --------------------------
    for d in slurmctld slurmd munged; do
        if ! _ls_alive "$(cat "$dir/run/$d.pid.sh")" "$d"; then
            _ls_err "recorded PID for $d is not $d (comm=$(cat "/proc/$(cat "$dir/run/$d.pid.sh")/comm" 2>/dev/null))"
            slurm_down "$dir"
            return 1
        fi
    done
    _ls_check_loopback "$dir" || { slurm_down "$dir"; return 1; }

    _ls_log "cluster up in $((SECONDS - t0))s: SLURM_CONF=$SLURM_CONF ctld_port=$ctld_port slurmd_port=$slurmd_port"
    return 0
}

# Fail if slurmctld or slurmd listens on anything but 127.0.0.1.
_ls_check_loopback() {
    local dir=$1 d pid lines addr n bad=0
    for d in slurmctld slurmd; do
        pid=$(cat "$dir/run/$d.pid.sh")
        lines=$(ss -Hltnp 2>/dev/null | grep -E "pid=$pid,") || true
        n=0
        while read -r _ _ _ addr _; do
            [[ -z $addr ]] && continue
            n=$((n + 1))
            if [[ $addr != 127.0.0.1:* ]]; then
                _ls_err "$d (pid $pid) listens on non-loopback address $addr"
                bad=1
            fi
        done <<<"$lines"
        if ((n == 0)); then
            _ls_err "$d (pid $pid) has no listening TCP socket"
            bad=1
        fi
    done
    # also UDP, just in case
    if ss -Hlunp 2>/dev/null | grep -qE "pid=($(cat "$dir/run/slurmctld.pid.sh")|$(cat "$dir/run/slurmd.pid.sh")),"; then
        _ls_err "a Slurm daemon has a UDP socket open"
        bad=1
    fi
    return "$bad"
}

# _ls_kill_family DIR... : TERM (then KILL) every process tagged with one of
# the DIRs, and their descendants. Used only when the PID files are gone.
_ls_kill_family() {
    local d p i pids=()
    for d in "$@"; do
        [[ -n $d ]] || continue
        mapfile -t -O "${#pids[@]}" pids < <(_ls_cluster_pids "$d")
    done
    ((${#pids[@]})) || return 0
    kill -TERM "${pids[@]}" 2>/dev/null
    for ((i = 0; i < 30; i++)); do
        local alive=0
        for p in "${pids[@]}"; do _ls_running "$p" && alive=1; done
        ((alive)) || return 0
        sleep 0.1
    done
    kill -KILL "${pids[@]}" 2>/dev/null
    return 0
}

# ---------------------------------------------------------------------------
# slurm_down [DIR]   -- stop everything started by slurm_up. Safe to repeat.
# ---------------------------------------------------------------------------
slurm_down() {
    local -; set +e # immune to the caller's errexit; options restored on return
    local dir=${1:-$LOCAL_SLURM_DIR}
    [[ -n $dir ]] || return 0
    if [[ ! -d $dir ]]; then
        # DIR already deleted (rm -rf before slurm_down?): no PID files left,
        # but the processes still carry LOCAL_SLURM_TAG=DIR.
        [[ $dir == / ]] || dir=${dir%/}
        if [[ -n $LOCAL_SLURM_DIR && ($LOCAL_SLURM_DIR == "$dir" || $LOCAL_SLURM_DIR == "$dir"/*) ]]; then
            _ls_kill_family "$dir" "$LOCAL_SLURM_DIR"
            LOCAL_SLURM_DIR=""
        else
            _ls_kill_family "$dir"
        fi
        return 0
    fi
    dir=$(cd "$dir" 2>/dev/null && pwd -P) || return 0
    # Convenience: `slurm_down "$tmp"` also stops a cluster started in "$tmp/sub".
    if [[ ! -d $dir/run && -n $LOCAL_SLURM_DIR && $LOCAL_SLURM_DIR == "$dir"/* ]]; then
        dir=$LOCAL_SLURM_DIR
    fi
    [[ -d $dir/run ]] || return 0
    local d pid pids=() extra=() p i

    # Politely cancel remaining jobs so slurmstepd can clean up its tasks.
    local ctld
    ctld=$(cat "$dir/run/slurmctld.pid.sh" 2>/dev/null)
    if _ls_alive "$ctld" slurmctld && [[ -n $(SLURM_CONF=$dir/slurm.conf squeue -h -o %i 2>/dev/null) ]]; then
        SLURM_CONF=$dir/slurm.conf scancel --quiet --full -u "$(id -un)" 2>/dev/null
        for ((i = 0; i < 30; i++)); do
            [[ -z $(SLURM_CONF=$dir/slurm.conf squeue -h -o %i 2>/dev/null) ]] && break
            sleep 0.1
        done
    fi

    # Snapshot the whole process family (stepds, job processes) first.
    mapfile -t extra < <(_ls_cluster_pids "$dir")

    # Daemons, by recorded PID (checking they are still what we started).
    for d in slurmd slurmctld munged; do
        pid=$(cat "$dir/run/$d.pid.sh" 2>/dev/null) || continue
        if _ls_alive "$pid" "$d"; then
            pids+=("$pid")
        fi
    done
    # Other members of the family: slurmstepd and descendants.
    for p in "${extra[@]}"; do
        [[ " ${pids[*]} " == *" $p "* ]] && continue
        _ls_running "$p" && pids+=("$p")
    done

    if ((${#pids[@]})); then
        kill -TERM "${pids[@]}" 2>/dev/null
        for ((i = 0; i < 30; i++)); do # up to 3 s
            local alive=0
            for p in "${pids[@]}"; do _ls_running "$p" && alive=1; done
            ((alive)) || break
            sleep 0.1
        done
        for p in "${pids[@]}"; do
            _ls_running "$p" && kill -KILL "$p" 2>/dev/null
        done
        for ((i = 0; i < 10; i++)); do # killed: give them a moment to vanish
            local left=0
            for p in "${pids[@]}"; do _ls_running "$p" && left=1; done
            ((left)) || break
            sleep 0.1
        done
    fi
    # Anything that appeared meanwhile (very unlikely): kill it.
    mapfile -t extra < <(_ls_cluster_pids "$dir")
    ((${#extra[@]})) && kill -KILL "${extra[@]}" 2>/dev/null

    rm -f "$dir"/run/*.pid.sh
    [[ $dir == "$LOCAL_SLURM_DIR" ]] && LOCAL_SLURM_DIR=""
    return 0
}

# ---------------------------------------------------------------------------
# slurm_wait_jobs [-t SECONDS] JOBID...
#   Poll squeue until none of the jobs is pending/running any more, then print
#   one line per job (array tasks separately) with its final state taken from
#   `scontrol show job`. Returns 0 iff all are COMPLETED; 2 on timeout.
# ---------------------------------------------------------------------------
slurm_wait_jobs() {
    local -; set +e # immune to the caller's errexit; options restored on return
    local timeout=${LOCAL_SLURM_WAIT_TIMEOUT:-120}
    if [[ ${1:-} == -t ]]; then timeout=$2; shift 2; fi
    (($#)) || { _ls_err "usage: slurm_wait_jobs [-t SECONDS] JOBID..."; return 1; }
    local ids ids_csv start=$SECONDS out
    ids=("$@")
    ids_csv=$(IFS=,; echo "${ids[*]}")
    while :; do
        # In 22.05 `squeue -j` already hides finished jobs; the explicit list
        # of non-final states keeps that true on versions/configs where -j
        # would also print COMPLETED/FAILED/... records.
        out=$(squeue -h -j "$ids_csv" -t PENDING,RUNNING,SUSPENDED,COMPLETING,CONFIGURING,REQUEUED,RESIZING,SIGNALING,STAGE_OUT,STOPPED -o '%i %T' 2>&1) ||
            { _ls_err "squeue failed: $out"; return 1; }
        [[ -z $out ]] && break
        if ((SECONDS - start >= timeout)); then
            _ls_err "timeout after ${timeout}s waiting for jobs; still active:"
            printf '%s\n' "$out" >&2
            return 2
        fi
        sleep 0.2
    done

    local id line rc=0 jid state reason ec kv
    for id in "${ids[@]}"; do
        out=$(scontrol -o show job "$id" 2>&1) || {
            _ls_err "scontrol show job $id failed: $out"
            rc=1
            continue
        }
        while IFS= read -r line; do
            [[ -z $line ]] && continue
            jid="" state="" reason="" ec=""
            local atid="" ajid=""
            for kv in $line; do
                case $kv in
                    JobId=*) jid=${kv#JobId=} ;;
                    ArrayJobId=*) ajid=${kv#ArrayJobId=} ;;
                    ArrayTaskId=*) atid=${kv#ArrayTaskId=} ;;
                    JobState=*) state=${kv#JobState=} ;;
                    Reason=*) reason=${kv#Reason=} ;;
                    ExitCode=*) ec=${kv#ExitCode=} ;;
                esac
            done
            [[ -n $ajid && -n $atid ]] && jid="${ajid}_${atid}"
            printf '%s %s exit=%s reason=%s\n' "$jid" "$state" "$ec" "$reason"
            [[ $state == COMPLETED ]] || rc=1
        done <<<"$out"
    done
    return "$rc"
}

# ---------------------------------------------------------------------------
# command-line mode
# ---------------------------------------------------------------------------
if [[ ${BASH_SOURCE[0]} == "$0" ]]; then
    case ${1:-} in
        check) slurm_check ;;
        up) shift; slurm_up "$@" ;;
        down) shift; slurm_down "$@" ;;
        wait)
            shift
            [[ -n ${1:-} ]] || { _ls_err "usage: $0 wait DIR JOBID..."; exit 1; }
            export SLURM_CONF="$1/slurm.conf"; shift
            slurm_wait_jobs "$@" ;;
        *)
            echo "usage: $0 check | up DIR | wait DIR JOBID... | down DIR" >&2
            exit 1 ;;
    esac
fi
