"""The output folder (``--out``): which folders a run may replace, and replacing one atomically.

A folder that a run writes carries :data:`MARKER`, a list of the files the run wrote.  A
folder may become an output folder if it is absent, holds no files, or holds only files
that its marker lists; ``force`` lifts that last condition but never the others: the
folder must not be, or contain, the current folder or a file the run reads.

The new contents are written into a temporary sibling folder and swapped with the old
folder in one ``renameat2(RENAME_EXCHANGE)`` system call (Linux), so that ``out`` always
holds either its old or its complete new contents; where the system cannot exchange, two
renames do it, with a moment in which ``out`` is absent.  Temporary folders are named
``.NAME.valvetrain-PID.XXXXXXXX.tmp``; those of a process that no longer runs (a run that
was killed) are removed by the next run into ``NAME``.
"""

from collections.abc import Iterator
from contextlib import contextmanager
import ctypes
import errno
from functools import cache
import os
from pathlib import Path
import re
import secrets
import shutil
import signal

from . import __version__
from .errors import InputError

MARKER = ".valvetrain-output"
"""File in every output folder: a comment line, then the path of every file the run wrote, one a line."""

KERNEL_FILE_SYSTEMS = (Path("/proc"), Path("/sys"))
"""Trees that hold no user files; a folder cannot be written there."""

_RENAME_EXCHANGE = 2
"""``renameat2`` flag: swap the two paths (linux/fs.h)."""

_AT_FDCWD = -100
"""``renameat2`` directory argument: paths relative to the current folder (linux/fcntl.h)."""


class OutFolderError(InputError):
    """An output folder that a run may not write; the message is one line naming the folder."""


def check_out(out, inputs=(), force=False) -> Path:
    """Check that ``out`` may become an output folder, before anything is computed or written.

    Parameters
    ----------
    out : str or Path
        The output folder as given.
    inputs : iterable of str or Path
        Files the run reads (the specification and the tables it names); ``out`` must not
        contain them, even with ``force``.
    force : bool
        Allow replacing a folder that holds files no valvetrain run wrote.

    Returns
    -------
    Path
        ``out`` made absolute, with symbolic links resolved.

    Raises
    ------
    OutFolderError
        The message names ``out``, what is wrong and what is allowed (an empty ``out``, which would be the current
        folder, is named as empty).
    """
    path = out_path(out).resolve()
    problem = (location_problem(path) or kind_problem(path) or input_problem(path, inputs)
               or (None if force else foreign_problem(path)))
    if problem:
        raise OutFolderError(f"{out}: {problem}")
    return path


def out_path(out) -> Path:
    """``out`` as a path; an empty one (a shell variable left empty), which would name the current folder, is refused
    as empty (:class:`OutFolderError`)."""
    if not str(out).strip():
        raise OutFolderError(f"{str(out)!r}: is empty; allowed: the path of a folder")
    return Path(out)


def location_problem(path) -> str | None:
    """Why a folder cannot be made at the absolute ``path``, or None."""
    cwd = Path.cwd().resolve()
    if path == cwd or path in cwd.parents:
        return "is the current folder or contains it; allowed: a folder outside the current one"
    for tree in KERNEL_FILE_SYSTEMS:
        if path == tree or tree in path.parents:
            return f"lies in {tree}, a kernel file system; allowed: a folder on a disk"
    parent = next(p for p in path.parents if os.path.lexists(p))
    if not parent.is_dir():
        return f"{parent} is a file; allowed: a path whose every parent is a folder"
    if not os.access(parent, os.W_OK | os.X_OK):
        return f"cannot create a folder in {parent} (no write permission); allowed: a folder where you can write"
    return None


def kind_problem(path) -> str | None:
    """Why what exists at ``path`` cannot be replaced by a folder (a file, a mount point), or None."""
    if os.path.lexists(path) and not path.is_dir():
        return "is a file; allowed: a folder (new, empty or a previous valvetrain output)"
    if path.is_dir() and path.is_mount():
        return "is a mount point; allowed: a folder inside it"
    return None


def input_problem(path, inputs) -> str | None:
    """Why replacing ``path`` would delete an input file, or None."""
    for f in inputs:
        real = Path(f).resolve()
        if real == path or path in real.parents:
            return (f"contains the input file {f}, which replacing the folder would delete; allowed: a folder that "
                    "holds no input file (even with --force)")
    return None


def foreign_problem(path) -> str | None:
    """Why replacing the folder ``path`` would delete files no valvetrain run wrote, or None."""
    if not path.is_dir():
        return None
    try:
        foreign = first_foreign_file(path)
    except OSError as exc:
        return f"cannot be read ({exc.strerror}); allowed: a folder whose files can be listed, or pass --force"
    if foreign is None:
        return None
    return (f"holds {foreign}, which valvetrain did not write; allowed: a new or empty folder or a previous valvetrain "
            "output; choose another folder or pass --force to replace this one and everything in it")


def first_foreign_file(folder) -> str | None:
    """The first file (or link) under ``folder`` that its :data:`MARKER` does not list, as a relative path, or None.

    Folders are not files: a folder that holds only empty folders has no foreign file.
    The walk stops at the first foreign file, so a large unrelated folder is not read through.
    """
    written = written_files(folder) | {MARKER}
    for root, dirs, files in os.walk(folder, onerror=_raise):
        rel = Path(root).relative_to(folder)
        links = [d for d in dirs if os.path.islink(os.path.join(root, d))]
        for name in files + links:
            if (rel / name).as_posix() not in written:
                return (rel / name).as_posix()
    return None


def _raise(exc):
    """Raise ``exc``: :func:`os.walk` skips an unreadable folder unless its ``onerror`` raises."""
    raise exc


def written_files(folder) -> set[str]:
    """The relative paths that ``folder``'s :data:`MARKER` lists (empty if it has none)."""
    try:
        text = (Path(folder) / MARKER).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return set()
    return {line for line in text.splitlines() if line and not line.startswith("#")}


def marker_text(folder) -> str:
    """The :data:`MARKER` of a completed ``folder``: every file under it, relative, sorted."""
    paths = sorted(Path(root, name).relative_to(folder).as_posix()
                   for root, _, files in os.walk(folder) for name in files)
    return (f"# written by valvetrain {__version__}; `valvetrain run/compare --out` replaces this folder when every "
            "file in it is listed below\n" + "".join(f"{p}\n" for p in paths))


@contextmanager
def atomic_folder(out, inputs=(), force=False) -> Iterator[Path]:
    """Yield a new temporary sibling folder of ``out`` and put it in place of ``out`` when the block completes.

    ``out`` is checked by :func:`check_out` (with ``inputs`` and ``force``) before the
    block and again just before the new folder is put in place.  A failure or an
    interruption inside the block removes the temporary folder and leaves ``out`` as it was
    (absent, or the previous contents).  The folder gets the permissions of the user's
    umask, like any new folder.
    """
    out = check_out(out, inputs, force)
    out.parent.mkdir(parents=True, exist_ok=True)
    remove_stale_temps(out)
    tmp = None
    try:
        # a SIGINT is held while the folder is made and while it is swapped in and the old one removed, so that it
        # finds ``tmp`` either unmade, or named here for the ``finally``, or gone
        with sigint_deferred():
            tmp = make_temp(out)
        yield tmp
        with sigint_deferred():
            (tmp / MARKER).write_text(marker_text(tmp), encoding="utf-8")
            check_out(out, inputs, force)
            swap(tmp, out)
            shutil.rmtree(tmp, ignore_errors=True)
            tmp = None
    finally:
        if tmp is not None:
            with sigint_deferred():
                shutil.rmtree(tmp, ignore_errors=True)


def temp_name(out) -> Path:
    """A fresh name for a temporary sibling of ``out``, carrying this process's id."""
    return out.parent / f".{out.name}.valvetrain-{os.getpid()}.{secrets.token_hex(4)}.tmp"


def make_temp(out) -> Path:
    """Create a temporary sibling folder of ``out`` (mode 0777 less the umask, as ``mkdir`` makes it)."""
    while True:
        path = temp_name(out)
        try:
            path.mkdir()
            return path
        except FileExistsError:
            continue


def remove_stale_temps(out) -> None:
    """Remove the temporary siblings of ``out`` that runs which no longer run left behind (killed runs).

    Only folders named ``.NAME.valvetrain-PID.XXXXXXXX.tmp`` for this ``out``, whose process
    ``PID`` is gone, are removed; nothing else is touched.
    """
    pattern = re.compile(re.escape(f".{out.name}.valvetrain-") + r"([1-9][0-9]{0,9})\.[0-9a-f]{8}\.tmp")
    with os.scandir(out.parent) as entries:
        for entry in entries:
            m = pattern.fullmatch(entry.name)
            if m and entry.is_dir(follow_symlinks=False) and not process_alive(int(m.group(1))):
                shutil.rmtree(entry.path, ignore_errors=True)


def process_alive(pid) -> bool:
    """Whether a process ``pid`` exists (signal 0 tests that and sends nothing)."""
    try:
        os.kill(pid, 0)
    except (ProcessLookupError, OverflowError):
        return False
    except PermissionError:  # another user's process
        pass
    return True


def swap(new, out) -> None:
    """Put the folder ``new`` at ``out``; what was at ``out`` (if anything) is then at ``new``, to be removed."""
    if not os.path.lexists(out):
        os.rename(new, out)
    elif not exchange(new, out):
        aside = temp_name(out)
        os.rename(out, aside)
        try:
            os.rename(new, out)
        except BaseException:
            os.rename(aside, out)
            raise
        os.rename(aside, new)


def exchange(a, b) -> bool:
    """Swap the paths ``a`` and ``b`` atomically; False where the system cannot.

    Linux's ``renameat2(..., RENAME_EXCHANGE)`` (kernel 3.15, glibc 2.28) through ctypes:
    Python's :mod:`os` has no ``renameat2``.  A file system or system without it gives
    False; any other failure raises :class:`OSError`.
    """
    renameat2 = _renameat2()
    if renameat2 is None:
        return False
    if renameat2(_AT_FDCWD, os.fsencode(a), _AT_FDCWD, os.fsencode(b), _RENAME_EXCHANGE) == 0:
        return True
    err = ctypes.get_errno()
    if err in (errno.ENOSYS, errno.EINVAL, errno.ENOTSUP, errno.EOPNOTSUPP):
        return False
    raise OSError(err, os.strerror(err), str(a), None, str(b))


@cache
def _renameat2():
    """The C library's ``renameat2``, or None where it has none."""
    try:
        fn = ctypes.CDLL(None, use_errno=True).renameat2
    except (OSError, AttributeError, TypeError):
        return None
    fn.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_uint]
    fn.restype = ctypes.c_int
    return fn


@contextmanager
def sigint_deferred() -> Iterator[None]:
    """Hold SIGINT (Ctrl-C) back during the block, so that it cannot stop an exchange or a removal half-way;
    a SIGINT that came meanwhile is raised as :class:`KeyboardInterrupt` right after the block."""
    if not hasattr(signal, "pthread_sigmask"):
        yield
        return
    previous = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, previous)
