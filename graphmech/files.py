"""Writing output files safely: the one place graphmech writes files."""
from __future__ import annotations

import errno
import os
import tempfile
from pathlib import Path


def write_atomic(path: str | os.PathLike[str], text: str | bytes) -> None:
    """Write via a temporary file in the same folder, then rename: never a half-written file.

    A symlink is followed (the link stays, its target is replaced); a target that is not a
    regular file (a device, a FIFO) is written directly, since renaming over it would replace it.
    The new file gets the usual permissions (0666 less the umask), not mkstemp's 0600.
    """
    data = text.encode("utf-8") if isinstance(text, str) else text
    given = os.fspath(path)
    path = Path(os.path.realpath(path))
    # the errors name the path as given (not the temporary file), with the usual errno and strerror
    if path.is_dir():
        raise IsADirectoryError(errno.EISDIR, "is a folder", given)
    if not path.parent.is_dir():
        raise FileNotFoundError(errno.ENOENT, "folder does not exist", given)
    if path.exists() and not path.is_file():
        with open(path, "wb") as f:
            f.write(data)
        return
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    except OSError as e:  # the folder refuses a new file: name the file asked for, not the temporary one
        raise OSError(e.errno, f"cannot write here ({e.strerror})", given) from None
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
