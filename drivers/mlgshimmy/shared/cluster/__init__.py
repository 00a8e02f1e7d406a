"""Submit staged job lists to Slurm or GNU parallel, follow them, resume them.

A job list is one shell command per line (a sweep point, an atlas cell, a part of a
staged figure).  A submission is a pipeline: stage 1's lines, then stage 2's (which may
read stage 1's results), ..., then one assembly command (`make fig11`, `python3 -m
mlgshimmy.studies.sweep summary`).  Usage (PYTHONPATH=drivers):

  python3 -m mlgshimmy.shared.cluster submit --name NAME --scheduler slurm|parallel
          (--stage FILE [--stage FILE ...] | --stages-from 'CMD ... {k}' [--stages N])
          [--allow-empty] [--assemble 'CMD'] [--per-task K] [--throttle M] [--jobs J]
          [--env VAR=VALUE ...] [--carry VAR ...] [--out DIR] [--assemble-opt=OPT ...]
          [--dry-run] [-- SBATCH OR PARALLEL OPTIONS ...]
  python3 -m mlgshimmy.shared.cluster status DIR [--json] [--wait [--timeout S]]
  python3 -m mlgshimmy.shared.cluster resume DIR [--dry-run] [-- EXTRA OPTIONS ...]

submit writes a new directory <out>/submit/<name>-<date>-<time>-<random>/ (out: the
repository's build/ by default) with one job file per stage (stage1.txt, ...; read-only,
never rewritten), assemble.txt, and manifest.json (job ids per stage and attempt).  Each
line there is the input line made self-sufficient: unless the line sets them itself, it
is prefixed with `export AUTO_DIR=... MLG_RUN_ROOT=... MLG_AUTO_THREADS=...
MPLBACKEND=Agg SOURCE_DATE_EPOCH=0;` (values from --env, else the submitting shell,
else the repository's defaults; paths made absolute; MLG_CPU_GUARD_SCALE too where the
submitting shell sets it), and with `cd <the submitting
directory> &&` unless it starts with an absolute cd.  So the tasks need nothing from
the environment they start in (sbatch --export=NONE works).  With --allow-empty, a
stage without lines (a `jobs --missing` list with nothing left) is kept and submits
nothing; when no stage has a line, only the assembly is submitted (none: nothing is).

slurm: stage k is one job array `sbatch --parsable -J <name>-s<k> --array=1-T[%M]
  -o <out>/logs/%x_%A_%a.out` of T = ceil(lines / K) tasks running mk/cluster/array-task.sh
  (K lines per task, --per-task), stage k + 1 depends on it with
  --dependency=afterok:<id> --kill-on-invalid-dep=yes, and the assembly
  (-J <name>-assemble, log %x_%j.out) on the last stage.  A failed task therefore
  cancels every later stage and the assembly instead of leaving them pending.  The
  options after `--` go to every sbatch (partition, account, --time, --mem, --export);
  --assemble-opt ones to the assembly's only, after them.
parallel: runs here, in the foreground, stage after stage: `parallel --joblog
  DIR/stage<k>.log --halt soon,fail=1 -j J [options after --] < DIR/stage<k>.txt`,
  then the assembly likewise (DIR/assemble.log); stops at the first failing stage.

status: every line of every stage and the assembly with its state: from the task's
  marks (array-task.sh writes DIR/marks/stage<k>/<line>: exit status, start, end, host,
  job id), squeue (-t all), and sacct, or, without accounting, the jobcomp/filetxt log;
  for parallel, from the job logs.  Counts per stage, then every line that failed, was
  cancelled or killed, never ran, or is running, with its stage, array index, line
  number, state, exit status, reason, job id, log and command (--all: pending and
  completed lines too; --json: all of it).  Exit status 0 when everything completed,
  3 while tasks are pending or running, 1 otherwise.
resume: slurm: resubmits, in the same directory and from the same job files, only the
  array indices that hold lines which did not complete (each such task skips its lines
  marked done), every later stage's incomplete lines, and the assembly; parallel: runs
  the pipeline again with --resume-failed (the job logs say what is done).  Refused
  while tasks of the submission are pending or running.

Standard library only (of the project, shared.paths alone): it runs on a login node
without numpy.  One job a module: refusal, environment, joblists, arrays, manifest,
submission, slurm, parallel, scheduler, status, summary, resume, arguments, __main__.
"""
