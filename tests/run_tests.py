"""Run test programs and summarise their results.

    run_tests.py [--timeout SECONDS] PROGRAM...

Each PROGRAM is an executable or a Python script (*.py, run with this
interpreter). A program prints one line per check, `ok <name>` or
`not ok <name> - <detail>`; other lines are passed through. A program that
exits non-zero without printing `not ok`, times out, or reports no check at
all counts as one failure. The last line printed is `N passed, N failed`; the
exit status is non-zero if anything failed.
"""
import argparse
import os
import signal
import subprocess
import sys
import time


def run_program(program, timeout):
    """Run one program, echo its output; return its (passed, failed) counts."""
    path = os.path.abspath(program)
    command = [sys.executable, path] if path.endswith(".py") else [path]
    print(f"=== {program}", flush=True)
    # A session of its own, so that a timeout also ends what the program
    # started (an AUTO executable that never stops, for instance).
    try:
        proc = subprocess.Popen(command, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, start_new_session=True)
    except OSError as exc:
        print(f"not ok {program} - cannot run: {exc}")
        return 0, 1
    try:
        output, _ = proc.communicate(timeout=timeout)
        status = proc.returncode
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        output, _ = proc.communicate()
        status = None

    passed = failed = 0
    for line in output.decode(errors="replace").splitlines():
        if line.startswith("ok "):
            passed += 1
            print(line)
        elif line.startswith("not ok "):
            failed += 1
            print(line)
        else:
            print("  | " + line)

    notes = []
    if status is None:
        notes.append(f"timed out after {timeout} s")
        failed += 1
    elif status != 0 and failed == 0:
        notes.append(f"exit status {status} without `not ok`")
        failed += 1
    elif passed + failed == 0:
        notes.append("reported no check")
        failed += 1
    for note in notes:
        print(f"not ok {program} - {note}")
    return passed, failed


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--timeout", type=float, default=600,
                        help="seconds allowed per program (default 600)")
    parser.add_argument("programs", nargs="*")
    args = parser.parse_args()

    summary = []
    for program in args.programs:
        start = time.monotonic()
        passed, failed = run_program(program, args.timeout)
        summary.append((program, passed, failed, time.monotonic() - start))

    print()
    print("Summary:")
    for program, passed, failed, seconds in summary:
        verdict = "FAIL" if failed else "pass"
        print(f"  {verdict}  {program}: {passed} passed, {failed} failed"
              f" ({seconds:.1f} s)")
    total_passed = sum(s[1] for s in summary)
    total_failed = sum(s[2] for s in summary)
    print(f"{total_passed} passed, {total_failed} failed")
    return 1 if total_failed else 0


if __name__ == "__main__":
    sys.exit(main())
