"""Writing output files (graphmech/files.py): whole or not at all, through a symlink, with the usual
permissions, and straight into what is not a regular file."""
from __future__ import annotations

import os
import stat

import pytest

from graphmech.files import write_atomic


def leftovers(folder):
    return sorted(p.name for p in folder.iterdir() if p.name.endswith(".tmp"))


def test_text_is_written_as_utf8_and_bytes_as_they_are(tmp_path):
    write_atomic(tmp_path / "a.svg", "μl = 0.002 m/mm\n")
    write_atomic(tmp_path / "b.bin", b"\x00\xff")
    assert (tmp_path / "a.svg").read_bytes() == "μl = 0.002 m/mm\n".encode("utf-8")
    assert (tmp_path / "b.bin").read_bytes() == b"\x00\xff"
    assert leftovers(tmp_path) == []


def test_an_existing_file_is_replaced_whole(tmp_path):
    path = tmp_path / "out.svg"
    path.write_text("old and longer than the new text\n")
    write_atomic(path, "new\n")
    assert path.read_text() == "new\n"


def test_the_new_file_has_the_usual_permissions_not_0600(tmp_path):
    old = os.umask(0o022)
    try:
        write_atomic(tmp_path / "f.txt", "x")
    finally:
        os.umask(old)
    assert stat.S_IMODE((tmp_path / "f.txt").stat().st_mode) == 0o644


def test_a_symlink_stays_and_its_target_is_replaced(tmp_path):
    target = tmp_path / "target.svg"
    target.write_text("old")
    link = tmp_path / "link.svg"
    link.symlink_to(target)
    write_atomic(link, "new")
    assert link.is_symlink() and target.read_text() == "new"


def test_a_folder_is_refused_and_nothing_left_behind(tmp_path):
    with pytest.raises(OSError, match="is a folder"):
        write_atomic(tmp_path, "x")
    assert leftovers(tmp_path) == []


def test_a_missing_folder_is_named_as_given_not_the_temporary_file(tmp_path):
    with pytest.raises(FileNotFoundError) as e:
        write_atomic(tmp_path / "none" / "out.svg", "x")
    assert (e.value.filename, e.value.strerror) == (str(tmp_path / "none" / "out.svg"), "folder does not exist")
    with pytest.raises(IsADirectoryError) as d:
        write_atomic(tmp_path, "x")
    assert (d.value.filename, d.value.strerror) == (str(tmp_path), "is a folder")


def test_a_failed_write_leaves_the_old_file_and_no_temporary(tmp_path, monkeypatch):
    path = tmp_path / "out.svg"
    path.write_text("old")

    def broken(src, dst):
        raise OSError("disk full")

    monkeypatch.setattr(os, "replace", broken)
    with pytest.raises(OSError, match="disk full"):
        write_atomic(path, "new")
    assert path.read_text() == "old" and leftovers(tmp_path) == []


def test_a_fifo_is_written_into_not_replaced(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    reader = os.open(fifo, os.O_RDONLY | os.O_NONBLOCK)  # a reader, so the writer's open does not block
    try:
        write_atomic(fifo, "through the pipe")
        assert os.read(reader, 100) == b"through the pipe"
    finally:
        os.close(reader)
    assert stat.S_ISFIFO(fifo.stat().st_mode)


def test_a_folder_that_refuses_new_files_is_named_with_the_file_asked_for(tmp_path):
    import os

    import pytest

    from graphmech.files import write_atomic

    if os.geteuid() == 0:  # root writes anywhere but /proc
        target = "/proc/graphmech-test.svg"
    else:
        locked = tmp_path / "locked"
        locked.mkdir(mode=0o500)
        target = str(locked / "x.svg")
    with pytest.raises(OSError) as e:
        write_atomic(target, "x")
    assert e.value.filename == target and "cannot write here" in str(e.value) and ".tmp" not in str(e.value)
    with pytest.raises(FileNotFoundError, match="folder does not exist"):
        write_atomic(tmp_path / "none" / "x.svg", "x")
