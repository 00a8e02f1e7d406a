"""The figure of what moved: every run of a reference set (the paper's gear,
grey) under the same run of a changed gear (stable solid, unstable dashed),
one panel per group of runs (the set's top level and each subdirectory,
e.g. Fig. 10's `figures` set, `table/` and `zero/`), each against the
run's continued parameter.  `make regress-<fig>` draws it at a changed gear
(SET, RHO/MU) or with WHAT_MOVED=1.

    what_moved_figure.py REFERENCE_DIR RUN_DIR OUT.png
"""
import collections
import os
import sys

import numpy

import compare_diagrams as cd
import reference_set

GREY = "0.6"


def groups(directory, runs):
    """{group ("" or a subdirectory): [run]} of the runs that exist there."""
    out = collections.OrderedDict()
    for run in sorted(runs):
        if os.path.exists(cd.b_file(directory, run)):
            out.setdefault(os.path.dirname(run), []).append(run)
    return out


def measure(branch):
    """(column, scale, label) of the amplitude a branch is drawn in."""
    if "psi_amp" in branch.coordnames:
        return "psi_amp", numpy.degrees(1.0), r"$\psi$ amplitude [deg]"
    return "L2-NORM", 1.0, "L2 norm"


def draw(reference_dir, run_dir, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from mlgshimmy.shared import draw as style

    runs = set(cd.run_names(reference_dir)) | {
        reference_set.run_name(rel) for rel in reference_set.run_files(run_dir)}
    panels = groups(reference_dir, runs)
    for group, names in groups(run_dir, runs).items():
        panels.setdefault(group, [])
        panels[group] = sorted(set(panels[group]) | set(names))
    fig, axes = plt.subplots(len(panels), 1, figsize=(9, 3.2 * len(panels)), squeeze=False)
    for ax, (group, names) in zip(axes[:, 0], panels.items()):
        for run in names:
            for directory, ours in ((reference_dir, False), (run_dir, True)):
                path = cd.b_file(directory, run)
                if not os.path.exists(path):
                    continue
                for branch in cd.read_branches(path):
                    x = branch.coordnames[0]
                    y, scale, label = measure(branch)
                    if ours:
                        style.plot_branch(ax, [branch], x, y, scale=scale, lw=1.3)
                    else:
                        ax.plot(branch[x], numpy.asarray(branch[y]) * scale, color=GREY,
                                lw=3.0, alpha=0.6, solid_capstyle="butt")
                    ax.set_xlabel(x)
                    ax.set_ylabel(label)
        ax.set_title(f"runs in {group}/" if group else "the figure's own runs")
    axes[0, 0].legend(handles=[
        Line2D([], [], color=GREY, lw=3.0, alpha=0.6, label="reference (the paper's gear)"),
        Line2D([], [], **style.STABLE_STYLE, label="your gear, stable"),
        Line2D([], [], **style.UNSTABLE_STYLE, label="your gear, unstable")],
        loc="upper left", fontsize="small")
    fig.suptitle(f"What moved: {os.path.basename(os.path.normpath(reference_dir))}, "
                 "reference and your gear")
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 3:
        print("usage: what_moved_figure.py REFERENCE_DIR RUN_DIR OUT.png", file=sys.stderr)
        return 2
    try:
        draw(*argv)
    except cd.DiagramFileError as exc:
        print(f"what_moved_figure: {exc}", file=sys.stderr)
        return 2
    print(f"what moved: drew {argv[2]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
