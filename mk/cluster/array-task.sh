#!/bin/bash
# One task of a job array: run line(s) of a job file (one shell command per line), and
# fail when there is nothing to run.
#
#   array-task.sh [-k K] [-n N] [-m MARKDIR] [-r] JOBFILE [TASK_ID]
#
#   JOBFILE   absolute path of the job file (a task may start in any directory)
#   TASK_ID   the task's index, 1, 2, ... (default $SLURM_ARRAY_TASK_ID)
#   -k K      the task runs lines (TASK_ID-1)*K+1 .. TASK_ID*K (default 1); the last task
#             of a list may have fewer
#   -n N      the job file must have exactly N lines (the count it was submitted with)
#   -m DIR    after each line, write DIR/<line number>: "<exit status> <start> <end>
#             <host> <job id>" (epoch seconds; "running ..." while it runs), atomically
#   -r        with -m: skip lines whose mark says 0 (a resubmission redoes the rest)
#
# Each line runs in its own `bash -c` (an `exit` or `cd` in one does not reach the next).
# A task with K lines runs all of them and exits with the first non-zero status among
# them. It fails, without running anything, when the job file is not an absolute path or
# cannot be read, when TASK_ID is not a whole number >= 1, when the file's length is not
# N, or when the task's first line is past the end of the file or empty.
set -eu
: "${PATH:=/usr/local/bin:/usr/bin:/bin}"   # --export=NONE may leave PATH unset
export PATH

die() { echo "array-task: $*" >&2; exit 2; }
whole() { [[ $1 =~ ^[1-9][0-9]*$ ]]; }

per_task=1 count= marks= redo=0
while getopts k:n:m:r opt; do
    case $opt in
        k) per_task=$OPTARG ;;
        n) count=$OPTARG ;;
        m) marks=$OPTARG ;;
        r) redo=1 ;;
        *) die "usage: array-task.sh [-k K] [-n N] [-m MARKDIR] [-r] JOBFILE [TASK_ID]" ;;
    esac
done
shift $((OPTIND - 1))
[ $# -ge 1 ] && [ $# -le 2 ] \
    || die "usage: array-task.sh [-k K] [-n N] [-m MARKDIR] [-r] JOBFILE [TASK_ID]"
file=$1
id=${2:-${SLURM_ARRAY_TASK_ID:-}}

case $file in
    /*) ;;
    *) die "job file '$file' is not an absolute path (the task runs in $(pwd))" ;;
esac
[ -f "$file" ] && [ -r "$file" ] || die "cannot read job file $file"
whole "$id" || die "task id '$id' is not a whole number >= 1 (no SLURM_ARRAY_TASK_ID?)"
whole "$per_task" || die "-k $per_task: lines per task must be a whole number >= 1"
if [ -n "$marks" ]; then
    case $marks in /*) ;; *) die "-m $marks is not an absolute path" ;; esac
    mkdir -p "$marks"
fi

lines=$(awk 'END { print NR }' "$file")
if [ -n "$count" ]; then
    whole "$count" || die "-n $count is not a whole number >= 1"
    [ "$lines" = "$count" ] \
        || die "$file has $lines lines, not the $count it was submitted with (rewritten?)"
fi
first=$(( (id - 1) * per_task + 1 ))
last=$(( id * per_task ))
[ "$first" -le "$lines" ] \
    || die "task $id needs line $first but $file has only $lines lines (list too short)"
[ "$last" -le "$lines" ] || last=$lines

host=$(hostname -s 2>/dev/null || echo unknown)
job=${SLURM_ARRAY_JOB_ID:+${SLURM_ARRAY_JOB_ID}_${SLURM_ARRAY_TASK_ID:-}}
job=${job:-${SLURM_JOB_ID:-$$}}

mark() {   # mark LINE TEXT
    [ -n "$marks" ] || return 0
    printf '%s\n' "$2" > "$marks/.$1.$$"
    mv -f "$marks/.$1.$$" "$marks/$1"
}

status=0
for ((i = first; i <= last; i++)); do
    line=$(sed -n "${i}p" "$file")
    [ -n "${line//[[:space:]]/}" ] || die "line $i of $file is empty"
    if [ "$redo" = 1 ] && [ -n "$marks" ] && [ -s "$marks/$i" ] \
        && [ "$(cut -d' ' -f1 "$marks/$i")" = 0 ]; then
        echo "array-task: line $i done before ($(cat "$marks/$i")), skipped" >&2
        continue
    fi
    start=$(date +%s)
    mark "$i" "running $start - $host $job"
    echo "array-task: line $i of $file on $host ($job): $line" >&2
    rc=0
    bash -c "$line" || rc=$?
    end=$(date +%s)
    mark "$i" "$rc $start $end $host $job"
    echo "array-task: line $i ended with status $rc after $((end - start)) s" >&2
    if [ "$rc" != 0 ] && [ "$status" = 0 ]; then status=$rc; fi
done
exit "$status"
