"""Outputs get the mode the umask gives, as open() and mkdir would: the
atomic writer's files (result.json, tables, figures, report, grid points)
and a reference set's directory were 0600 and 0700 whatever the umask."""
import glob
import os
import shutil
import stat

import pytest

import compare_diagrams as cd
import reference_set as rs
from mlgshimmy.shared.jobs.atomic import write_atomic, write_json, write_text

UMASKS = {0o022: (0o644, 0o755), 0o002: (0o664, 0o775)}


@pytest.fixture(params=sorted(UMASKS), ids=lambda m: f"umask{m:03o}")
def umask(request):
    old = os.umask(request.param)
    yield request.param
    os.umask(old)


def mode(path):
    return stat.S_IMODE(os.stat(path).st_mode)


def test_the_atomic_writer_gives_the_umask_mode(tmp_path, umask):
    file_mode = UMASKS[umask][0]
    written = [write_json(str(tmp_path / "result.json"), {"a": 1}),
               write_text(str(tmp_path / "table.txt"), "x\n"),
               write_atomic(str(tmp_path / "fig.png"), lambda out: out.write(b"\x89PNG"), "wb")]
    assert [oct(mode(p)) for p in written] == [oct(file_mode)] * 3
    # replacing a file gives the mode afresh
    os.chmod(written[0], 0o600)
    write_json(written[0], {"a": 2})
    assert oct(mode(written[0])) == oct(file_mode)
    assert sorted(os.listdir(tmp_path)) == ["fig.png", "result.json", "table.txt"]


def test_a_replaced_reference_set_gives_the_umask_mode(tmp_path, umask):
    file_mode, directory_mode = UMASKS[umask]
    run = tmp_path / "run"
    run.mkdir()
    for path in glob.glob(os.path.join(cd.REFERENCE_ROOT, "fig07", "b.*")):
        shutil.copy(path, run)
    root = tmp_path / "refs"
    assert rs.replace("fig07", str(run), root=str(root))
    target = root / "fig07"
    assert oct(mode(target)) == oct(directory_mode)
    assert {oct(mode(p)) for p in target.iterdir()} == {oct(file_mode)}
