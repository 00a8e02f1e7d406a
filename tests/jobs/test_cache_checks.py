"""The result cache checks itself: an edited number, a truncated or empty
file, another figure's file and a NaN on write are refused with a message
naming the file and what to run; make's plot step exits with one line."""
import json
import os
import subprocess
import sys

import pytest

from mlgshimmy.shared import jobs


@pytest.fixture
def root(tmp_path, monkeypatch):
    monkeypatch.setenv("MLG_RUN_ROOT", str(tmp_path))
    jobs.write("figZ", {"numbers": {"H1 [m/s]": 1.458, "far": float("inf")}, "curve": [1.0, 2.0]})
    jobs.write("figZ", {"x": 1}, part="slice_1")
    return tmp_path


def result(root):
    return root / "figZ" / "result.json"


def test_a_whole_result_reads_back(root):
    assert jobs.read("figZ") == {"numbers": {"H1 [m/s]": 1.458, "far": float("inf")},
                                 "curve": [1.0, 2.0]}
    assert jobs.read("figZ", "slice_1") == {"x": 1}


@pytest.mark.parametrize("edit", ["999", "NaN"])
def test_an_edited_number_is_refused(root, edit):
    text = result(root).read_text().replace("1.458", edit)
    result(root).write_text(text)
    with pytest.raises(jobs.BadResult, match=r"figZ: .*result.json fails its checksum.*make figZ"):
        jobs.read("figZ")


@pytest.mark.parametrize("cut", [0, 13, -2])
def test_a_cut_file_is_refused_naming_it(root, cut):
    text = result(root).read_text()
    result(root).write_text(text[:cut] if cut else "")
    with pytest.raises(jobs.BadResult, match=r"result.json is not a whole result .*make figZ"):
        jobs.read("figZ")


def test_another_figures_file_is_refused(root):
    os.makedirs(root / "figW", exist_ok=True)
    os.replace(result(root), root / "figW" / "result.json")
    with pytest.raises(jobs.BadResult, match="is the cached 'figZ' part None, not 'figW'"):
        jobs.read("figW")
    part = root / "figZ" / "parts" / "slice_1.json"
    os.replace(part, root / "figZ" / "parts" / "slice_2.json")
    with pytest.raises(jobs.BadResult, match="part 'slice_1', not 'figZ' part 'slice_2'"):
        jobs.read("figZ", "slice_2")


def test_a_nan_is_refused_on_write(root):
    with pytest.raises(jobs.BadResult, match=r"data\['numbers'\]\['H2'\] is NaN"):
        jobs.write("figZ", {"numbers": {"H1": 1.0, "H2": float("nan")}})
    assert jobs.read("figZ")["numbers"]["H1 [m/s]"] == 1.458     # the old result stays


def test_a_nan_is_refused_on_read(root):
    """A NaN stored with a matching checksum (written by hand or an older
    writer) was read and printed as "Hopf at V = nan m/s"."""
    stored = json.loads(result(root).read_text())
    stored["data"]["numbers"]["H1 [m/s]"] = float("nan")
    stored["sha256"] = jobs.cache.checksum(stored["data"])
    result(root).write_text(json.dumps(stored))
    with pytest.raises(jobs.BadResult) as error:
        jobs.read("figZ")
    assert str(error.value) == (f"figZ: {result(root)} holds a NaN at data['numbers']['H1 [m/s]'], "
                                "which no result may; remove it and run `make figZ`")


def test_the_plot_step_says_one_line(tmp_path):
    env = dict(os.environ, MLG_RUN_ROOT=str(tmp_path))
    subprocess.run([sys.executable, "-m", "mlgshimmy.figures.fig07", "--compute"], env=env,
                   check=True, capture_output=True)
    path = tmp_path / "fig07" / "result.json"
    stored = json.loads(path.read_text())
    stored["data"]["numbers"] = {k: 999.0 for k in stored["data"].get("numbers", {"x": 0})}
    path.write_text(json.dumps(stored))
    proc = subprocess.run([sys.executable, "-m", "mlgshimmy.figures.fig07", "--plot"], env=env,
                          capture_output=True, text=True)
    assert proc.returncode == 1
    assert proc.stderr.strip().splitlines() == [
        f"fig07: {path} fails its checksum (edited or damaged); remove it and run `make fig07`"]


def test_the_provenance_names_what_the_result_was_computed_with(root, monkeypatch):
    monkeypatch.setenv("MLG_AUTO_THREADS", "3")
    jobs.write("figZ", {"x": 2})
    stored = json.loads(result(root).read_text())["provenance"]
    assert stored["auto_threads"] == "3" and stored["auto_dir"]
    assert stored["parameter_set"] == "figures" and stored["git_commit"]
    model = os.path.join(jobs.cache.paths.BUILD, "models", "mlg.exe")
    if os.path.exists(model):
        assert len(stored["model_sha256"]) == 64
