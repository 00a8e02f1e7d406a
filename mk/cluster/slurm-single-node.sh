#!/bin/bash
# A private one-node Slurm on this machine (Debian 12, Slurm 22.05, root, no systemd),
# for trying the cluster path (docs/cluster.md) and for tests/cluster/test_cluster_slurm.py:
# munge + slurmctld + slurmd on this host, one partition "debug", every file in one
# state directory. Nothing under /etc/slurm, /etc/munge or /run is written or read, so
# an existing Slurm or munge set-up on the machine is left as it is.
#
#   mk/cluster/slurm-single-node.sh start   install the packages (first time), configure,
#                                           start the daemons, wait for an idle node
#   mk/cluster/slurm-single-node.sh stop    cancel this cluster's jobs, stop the three
#                                           daemons by their pid files (no name matching)
#   mk/cluster/slurm-single-node.sh env     print the line that points clients at it
#   mk/cluster/slurm-single-node.sh install only install the packages (slurm-wlm munge parallel)
#
# Settings (environment):
#   SLURM_STATE_DIR  the state directory (default build/slurm of this repository); its
#                    parents must be searchable by the munge user (not under a 0700 dir)
#   NCPUS            CPUs of the node (default: nproc)
#   MEMORY_MB        its memory for sbatch --mem (default: 90 % of MemTotal)
#   SLURMCTLD_PORT, SLURMD_PORT   ports (default 6817, 6818; refused if in use)
#
# Clients (sbatch, squeue, sacct, mlgshimmy.shared.cluster) find this cluster through
# SLURM_CONF=$SLURM_STATE_DIR/slurm.conf (`start` and `env` print the export line).
# Without slurmdbd, finished tasks are recorded by jobcomp/filetxt in
# $SLURM_STATE_DIR/log/jobcomp.log (`sacct -c`).
#
# Exit status: 0 ok, 1 failure, 2 usage, 77 cannot be set up here: the packages are
# missing and cannot be installed (apt-get failed, or not root), or `start` is not run
# as root. Tests skip on 77 only, with the message.
#
# Never purge or autoremove libmunge2 or munge afterwards: Debian's SUNDIALS pulls
# openmpi -> pmix -> munge, and an autoremove takes the SUNDIALS libraries with it.
set -euo pipefail
# the daemons, mungekey and runuser are in the sbin directories, which a non-login
# root shell (a container's, CI's) may not have on PATH
export PATH=$PATH:/usr/local/sbin:/usr/sbin:/sbin

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
D=${SLURM_STATE_DIR:-$root/build/slurm}
NCPUS=${NCPUS:-$(nproc)}
CTLD_PORT=${SLURMCTLD_PORT:-6817}
SLURMD_PORT=${SLURMD_PORT:-6818}
PACKAGES="slurm-wlm munge parallel"
INSTALL_TRIES=3 INSTALL_WAIT=20   # apt-get tries, and seconds between them (install_packages)

die() { echo "slurm-single-node: $*" >&2; exit 1; }

# pid of a daemon from its pid file if that process is alive and is the named program
alive() {   # alive PIDFILE COMM
    local pid
    [ -s "$1" ] || return 1
    pid=$(cat "$1")
    [[ $pid =~ ^[0-9]+$ ]] || return 1
    [ "$(cat "/proc/$pid/comm" 2>/dev/null)" = "$2" ] || return 1
    echo "$pid"
}

stop_one() {   # stop_one PIDFILE COMM
    local pid
    if pid=$(alive "$1" "$2"); then
        kill "$pid"
        for _ in $(seq 40); do kill -0 "$pid" 2>/dev/null || break; sleep 0.25; done
        if kill -0 "$pid" 2>/dev/null; then
            echo "slurm-single-node: $2 ($pid) still running after 10 s, sent SIGKILL" >&2
            kill -9 "$pid" 2>/dev/null || true
        fi
        echo "stopped $2 ($pid, $1)"
    fi
    rm -f "$1"
}

stop() {
    [ -d "$D" ] || { echo "slurm-single-node: no state directory $D, nothing to stop"; return 0; }
    export SLURM_CONF=$D/slurm.conf
    if alive "$D/slurmctld.pid" slurmctld >/dev/null; then
        # every job of this private cluster is ours: none may outlive its slurmd
        local ids
        ids=$(squeue -h -o %A 2>/dev/null | sort -u | tr '\n' ' ')
        [ -z "${ids// /}" ] || scancel $ids 2>/dev/null || true
        for _ in $(seq 40); do
            [ -z "$(squeue -h -o %A 2>/dev/null)" ] && break
            sleep 0.25
        done
    fi
    stop_one "$D/slurmd.pid" slurmd
    stop_one "$D/slurmctld.pid" slurmctld
    stop_one "$D/munge/munged.pid" munged
}

# munged wants its socket reachable by every user: each directory above it searchable
searchable_by_all() {
    local dir=$1
    while [ "$dir" != / ]; do
        [ "$(stat -c %A "$dir" | cut -c10)" = x ] || [ "$(stat -c %A "$dir" | cut -c10)" = t ] \
            || { echo "$dir"; return 1; }
        dir=$(dirname "$dir")
    done
}

port_free() {   # true if nothing listens on 127.0.0.1:$1
    ! (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null
}

installed() {
    command -v slurmctld >/dev/null && command -v slurmd >/dev/null \
        && command -v munged >/dev/null && command -v mungekey >/dev/null \
        && command -v parallel >/dev/null
}

install_packages() {
    installed && return 0
    if [ "$(id -u)" != 0 ]; then
        echo "slurm-single-node: $PACKAGES are not installed and this is not root" >&2
        exit 77
    fi
    echo "slurm-single-node: installing $PACKAGES"
    export DEBIAN_FRONTEND=noninteractive
    # the postinsts try invoke-rc.d start, which a container refuses: harmless, we start below.
    # Another apt-get (a second test worker installing the same packages) holds the lists
    # lock, which DPkg::Lock::Timeout does not wait for: try again, up to INSTALL_TRIES times.
    local try
    for try in $(seq "$INSTALL_TRIES"); do
        if apt-get -o DPkg::Lock::Timeout=300 update -qq \
                && apt-get -o DPkg::Lock::Timeout=300 install -y -qq $PACKAGES >/dev/null; then
            return 0
        fi
        installed && return 0
        [ "$try" -lt "$INSTALL_TRIES" ] && sleep "$INSTALL_WAIT"
    done
    echo "slurm-single-node: apt-get install $PACKAGES failed ($INSTALL_TRIES tries)" >&2
    exit 77
}

start() {
    install_packages   # exits 77 if they are missing and cannot be installed
    if [ "$(id -u)" != 0 ]; then   # slurmd runs jobs as their users: only root can
        echo "slurm-single-node: start needs root (slurmd runs jobs as their users)" >&2
        exit 77
    fi
    local H pid MEMORY
    H=$(hostname -s)
    # without RealMemory the node has 1 MB and every sbatch --mem is refused; 90 % of it
    MEMORY=${MEMORY_MB:-$(awk '/^MemTotal:/ { print int($2 / 1024 * 0.9) }' /proc/meminfo)}
    if pid=$(alive "$D/slurmctld.pid" slurmctld); then
        echo "slurm-single-node: already running in $D (slurmctld $pid); stop it first" >&2
        echo "export SLURM_CONF=$D/slurm.conf"
        exit 1
    fi
    for port in "$CTLD_PORT" "$SLURMD_PORT"; do
        port_free "$port" || die "port $port is in use (another Slurm?); set SLURMCTLD_PORT and SLURMD_PORT"
    done
    mkdir -p "$D"
    D=$(cd "$D" && pwd)
    local closed
    closed=$(searchable_by_all "$D") \
        || die "$closed is not searchable by every user, which munge needs for its socket: set SLURM_STATE_DIR to a directory under searchable ones (e.g. under /var/tmp)"
    install -d -m 0755 "$D/ctld" "$D/slurmd" "$D/log"
    # munge: a private key, socket and pid file. munged wants its directory owned by
    # munge and searchable by every user (clients connect to the socket in it).
    install -d -o munge -g munge -m 0711 "$D/munge"
    if [ ! -s "$D/munge/munge.key" ]; then
        mungekey --create --keyfile="$D/munge/munge.key"
    fi
    chown munge:munge "$D/munge/munge.key"; chmod 0400 "$D/munge/munge.key"
    local sock=$D/munge/munge.socket
    runuser -u munge -- /usr/sbin/munged --socket="$sock" --key-file="$D/munge/munge.key" \
        --pid-file="$D/munge/munged.pid" --log-file="$D/munge/munged.log" \
        --seed-file="$D/munge/munged.seed" \
        || die "munged did not start: $(tail -n 3 "$D/munge/munged.log" 2>/dev/null)"
    munge -n --socket="$sock" | unmunge --socket="$sock" >/dev/null \
        || { stop; die "munge does not answer on $sock"; }
    # ClusterName is mandatory in 22.05; CR_CPU makes each CPU a slot; no cgroups (no
    # systemd here), no slurmdbd: jobcomp/filetxt keeps each finished task for sacct -c.
    cat > "$D/slurm.conf" <<CONF
# written by mk/cluster/slurm-single-node.sh; a private one-node cluster
ClusterName=local
SlurmctldHost=$H
SlurmctldPort=$CTLD_PORT
SlurmdPort=$SLURMD_PORT
SlurmUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$sock
MailProg=/bin/true
MpiDefault=none
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc=$D/log/jobcomp.log
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MinJobAge=600
StateSaveLocation=$D/ctld
SlurmdSpoolDir=$D/slurmd
SlurmctldPidFile=$D/slurmctld.pid
SlurmdPidFile=$D/slurmd.pid
SlurmctldLogFile=$D/log/slurmctld.log
SlurmdLogFile=$D/log/slurmd.log
NodeName=$H NodeAddr=127.0.0.1 CPUs=$NCPUS RealMemory=$MEMORY State=UNKNOWN
PartitionName=debug Nodes=$H Default=YES MaxTime=INFINITE State=UP
CONF
    export SLURM_CONF=$D/slurm.conf
    slurmctld || { stop; die "slurmctld did not start: $(tail -n 5 "$D/log/slurmctld.log")"; }
    slurmd || { stop; die "slurmd did not start: $(tail -n 5 "$D/log/slurmd.log")"; }
    local idle=
    for _ in $(seq 120); do
        if sinfo -h -N -o '%T' 2>/dev/null | grep -qx idle; then idle=1; break; fi
        sleep 0.5
    done
    if [ -z "$idle" ]; then
        sinfo -N 2>&1 || true
        tail -n 5 "$D/log/slurmctld.log" "$D/log/slurmd.log" >&2 || true
        stop
        die "the node did not become idle within 60 s"
    fi
    sinfo
    srun -N1 -n1 true || { stop; die "srun on the new node failed"; }
    echo "slurm-single-node: running in $D; for clients:"
    echo "export SLURM_CONF=$D/slurm.conf"
}

case "${1:-}" in
    start) start ;;
    stop) stop ;;
    env) echo "export SLURM_CONF=$D/slurm.conf" ;;
    install) install_packages ;;
    *) echo "usage: $0 start|stop|env|install   (SLURM_STATE_DIR=$D)" >&2; exit 2 ;;
esac
