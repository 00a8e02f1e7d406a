"""Reference sets (tests/reference/<fig>/): their manifest, and replacing one
atomically (`make refs-<fig>`).

    reference_set.py replace FIG RUN_DIR [--root DIR]   new set from a run
    reference_set.py verify FIG [--root DIR]            check against its MANIFEST
    reference_set.py publish NEW TARGET                 swap a directory in

A set holds the b-file of every run the figure writes (subdirectories kept;
or only the runs its runs.json selects: {"store": ["eq", "F1/*", ...],
"reason": "..."}, shell patterns on run names such as "zero/po1"), the
settings files it had (tolerances.json, labels.json, runs.json), the
figure's named points (named.json, from its result.json: named_points.py) and
MANIFEST: one line "<sha256>  <path>" per file. A file missing, extra or
changed is an error naming it.

replace writes the new set beside the old one (.<fig>.new-<pid>-<random>), verifies
it (manifest, and every b-file equal to the run's), then exchanges the two
directories in one rename (renameat2 RENAME_EXCHANGE) and deletes the old
one. Killed at any moment, it leaves <fig>/ the complete old set or the
complete new one; leftovers of a killed replace (dot-directories) are
removed by the next one. A replace that fails (a full disk: the new set does
not fit) removes its partial copy itself and says so in one line, the old
set left as it was; exit status 2.
"""
import argparse
import ctypes
import errno
import fnmatch
import hashlib
import json
import os
import shutil
import signal
import sys

import named_points  # this directory: run as a script, or pytest's pythonpath

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
REFERENCE_ROOT = os.path.join(ROOT, "tests", "reference")
MANIFEST = "MANIFEST"
SELECTION = "runs.json"
# Test hook (tests/regression/test_reference_sets.py): SIGKILL this process when it
# reaches the named step, as an interrupt there would.
STOP_AT = os.environ.get("MLG_REFS_KILL_AT")


class SetError(Exception):
    """A reference set that does not match its manifest (names the file)."""


def os_error_text(exc):
    """'No space left on device writing <path>' for an OSError."""
    path = exc.filename2 if getattr(exc, "filename2", None) else exc.filename
    what = exc.strerror or str(exc)
    return f"{what} writing {path}" if path else what


def _step(name):
    if STOP_AT == name:
        os.kill(os.getpid(), signal.SIGKILL)


def files_under(directory):
    """Relative paths of every file under directory, sorted, MANIFEST and
    dot-entries left out."""
    out = []
    for parent, dirs, files in os.walk(directory):
        dirs[:] = sorted(d for d in dirs if not d.startswith("."))
        for name in files:
            if not name.startswith(".") and not (parent == directory and name == MANIFEST):
                out.append(os.path.relpath(os.path.join(parent, name), directory))
    return sorted(out)


def digest(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def write_manifest(directory):
    lines = [f"{digest(os.path.join(directory, rel))}  {rel}\n" for rel in files_under(directory)]
    with open(os.path.join(directory, MANIFEST), "w") as f:
        f.writelines(lines)
        f.flush()
        os.fsync(f.fileno())


def verify(directory):
    """The b-file runs of a set (["eq", "zero/eq", ...]) after checking every
    file against MANIFEST; SetError names the first file missing, extra or
    changed."""
    path = os.path.join(directory, MANIFEST)
    if not os.path.isdir(directory):
        raise SetError(f"{directory}: no such reference directory (`make refs-<fig>` creates it)")
    if not os.path.isfile(path):
        raise SetError(f"{path}: missing (every reference set has one; "
                       "`make refs-<fig>` writes the set with it)")
    listed = {}
    with open(path) as f:
        for number, line in enumerate(f, 1):
            parts = line.rstrip("\n").split("  ", 1)
            if len(parts) != 2 or len(parts[0]) != 64:
                raise SetError(f"{path}:{number}: not a '<sha256>  <path>' line")
            listed[parts[1]] = parts[0]
    present = set(files_under(directory))
    for rel in sorted(listed):
        if rel not in present:
            raise SetError(f"{os.path.join(directory, rel)}: listed in {MANIFEST} but missing")
    for rel in sorted(present - set(listed)):
        raise SetError(f"{os.path.join(directory, rel)}: not listed in {MANIFEST} (extra file)")
    for rel, expected in sorted(listed.items()):
        if digest(os.path.join(directory, rel)) != expected:
            raise SetError(f"{os.path.join(directory, rel)}: changed since {MANIFEST} was "
                           "written (regenerate with `make refs-<fig>`)")
    runs = [run_name(rel) for rel in listed if os.path.basename(rel).startswith("b.")]
    if not runs:
        raise SetError(f"{directory}: no b-files in the reference set")
    return sorted(runs)


def run_files(run_dir):
    """Relative paths of the b-files under a run directory."""
    return [rel for rel in files_under(run_dir) if os.path.basename(rel).startswith("b.")]


def run_name(rel):
    """"sub/b.name" -> "sub/name"."""
    return os.path.join(os.path.dirname(rel), os.path.basename(rel)[2:])


def stored(reference_dir, runs):
    """The runs (names) a set stores: those its runs.json selects, else all."""
    path = os.path.join(reference_dir, SELECTION)
    if not os.path.exists(path):
        return list(runs)
    try:
        with open(path) as f:
            patterns = json.load(f)["store"]
        if not all(isinstance(p, str) and p for p in patterns):
            raise ValueError("store must list run-name patterns")
    except (ValueError, KeyError, TypeError) as exc:
        raise SetError(f"{path}: expected {{\"store\": [\"pattern\", ...], \"reason\": ...}} "
                       f"({exc})") from exc
    return [r for r in runs if any(fnmatch.fnmatchcase(r, p) for p in patterns)]


_libc = ctypes.CDLL(None, use_errno=True)
RENAME_EXCHANGE = 2
AT_FDCWD = -100


def exchange(a, b):
    """Swap two directories in one step (Linux renameat2)."""
    if _libc.renameat2(AT_FDCWD, a.encode(), AT_FDCWD, b.encode(), RENAME_EXCHANGE) != 0:
        err = ctypes.get_errno()
        raise OSError(err, f"renameat2({a}, {b}, RENAME_EXCHANGE): {os.strerror(err)}")


def publish(new, target):
    """Put directory `new` in place of `target` atomically; the old one is
    deleted.  An OSError means `target` is as it was (`new` too)."""
    if os.path.isdir(target):
        exchange(new, target)
        _step("exchanged")
        try:
            shutil.rmtree(new)
        except OSError as exc:
            raise SetError(f"{target}: replaced, but the old one (now {new}) could not be "
                           f"removed: {os_error_text(exc)}") from exc
    else:
        os.rename(new, target)


def remove_leftovers(root, figure):
    """Directories left by a killed replace of `figure` whose process is gone."""
    for entry in os.listdir(root):
        if entry.startswith(f".{figure}.new-"):
            pid = entry[len(f".{figure}.new-"):].split("-")[0]
            if pid.isdigit() and os.path.exists(f"/proc/{pid}") and int(pid) != os.getpid():
                continue
            shutil.rmtree(os.path.join(root, entry), ignore_errors=True)


def replace(figure, run_dir, root=REFERENCE_ROOT):
    """Make root/figure the set of every b-file under run_dir, keeping the
    old set's settings files; atomic (module docstring)."""
    import compare_diagrams as cd   # puts mlgshimmy on the path, or says how
    from mlgshimmy.shared.jobs.atomic import new_directory
    target = os.path.join(root, figure)
    os.makedirs(root, exist_ok=True)
    remove_leftovers(root, figure)
    selected = set(stored(target, map(run_name, run_files(run_dir))) if os.path.isdir(target)
                   else map(run_name, run_files(run_dir)))
    runs = [rel for rel in run_files(run_dir) if run_name(rel) in selected]
    if not runs:
        raise SetError(f"{run_dir}: the figure wrote no b-files (that {SELECTION} selects)")
    # created here, under a name no one can foresee (the pid for remove_leftovers)
    new = new_directory(root, f".{figure}.new-{os.getpid()}-")
    try:
        _fill(new, target, run_dir, runs, cd)
        publish(new, target)
    except BaseException as exc:
        # `new` is the partial new set, or after the exchange the old one
        # that publish could not delete: either way it goes
        shutil.rmtree(new, ignore_errors=True)
        if not isinstance(exc, OSError):
            raise
        # an OSError: nothing was published, the old set is as it was
        full = exc.errno in (errno.ENOSPC, errno.EDQUOT)
        raise SetError(f"{target}: the new set {'did not fit' if full else 'was not written'} "
                       f"({os_error_text(exc)}); {target} "
                       f"{'left as it was' if os.path.isdir(target) else 'not created'}, the "
                       f"partial copy {new} removed") from exc
    return [run_name(r) for r in runs]


def _fill(new, target, run_dir, runs, cd):
    """Copy the runs and the old set's settings files into `new`, write its
    manifest and verify it against the run directory."""
    for rel in runs:
        os.makedirs(os.path.join(new, os.path.dirname(rel)), exist_ok=True)
        shutil.copyfile(os.path.join(run_dir, rel), os.path.join(new, rel))
        _step("copying")
    if os.path.isdir(target):
        for rel in files_under(target):
            if not os.path.basename(rel).startswith("b."):
                shutil.copyfile(os.path.join(target, rel), os.path.join(new, rel))
    numbers = named_points.of_run(run_dir)
    if numbers is not None:
        named_points.write(new, numbers)
    write_manifest(new)
    _step("manifest")
    verify(new)
    try:
        result = cd.compare_dirs(new, run_dir, rtol=0.0, atol=0.0, raw=True)
    except cd.DiagramFileError as exc:
        raise SetError(f"{new}: cannot compare the copied set with {run_dir}: {exc}") from exc
    if not result.ok():
        raise SetError(f"{new}: the copied set differs from {run_dir}:\n{result.report()}")
    _step("verified")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("replace")
    p.add_argument("figure")
    p.add_argument("run_dir")
    p.add_argument("--root", default=REFERENCE_ROOT)
    p = sub.add_parser("verify")
    p.add_argument("figure")
    p.add_argument("--root", default=REFERENCE_ROOT)
    p = sub.add_parser("publish")
    p.add_argument("new")
    p.add_argument("target")
    args = parser.parse_args(argv)
    try:
        if args.command == "replace":
            runs = replace(args.figure, os.path.abspath(args.run_dir), os.path.abspath(args.root))
            print(f"refs: replaced {os.path.relpath(os.path.join(args.root, args.figure))}/ "
                  f"({len(runs)} runs: {' '.join(runs)})")
        elif args.command == "verify":
            runs = verify(os.path.join(args.root, args.figure))
            print(f"refs: {args.figure}: {len(runs)} runs match {MANIFEST}")
        else:
            publish(os.path.abspath(args.new), os.path.abspath(args.target))
    except (SetError, OSError) as exc:
        print(f"refs: error: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
