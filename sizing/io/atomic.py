"""The one output writer of every command (docs/formats.md: nothing half-written).

Two shapes of output:

- a folder (``solve --out DIR``, ``diagnose --out DIR``): ``write_folder``
  writes the whole set into a temporary sibling folder, then swaps it in
  with two renames while SIGINT/SIGTERM are held back, so the folder holds
  either every old file or every new one, never a mix. Entries of an
  existing folder that are not outputs (a user's notes) are carried over by
  hard link;
- loose files (``fit --out FILE`` and FILE.html beside it, ``catalog add``):
  ``write_files`` writes each to a temporary sibling, then renames them all
  while signals are held back, restoring the old files if a rename fails.

``check_folder`` / ``check_files`` are called by a command *before* any
work starts (and again by the writers): the destination must be a folder
where a folder is expected and a file where a file is expected, writable,
and never one of the command's inputs. Every refusal is an ``InputError``
naming the option, so the CLI exits 2 with one line. Temporary files and
folders are removed on any failure, KeyboardInterrupt included.

Durable as well as atomic: every file is flushed to disk (``os.fsync``)
before it is renamed into place, and the folders that hold the renamed
entries are fsynced after the swap, so a power cut leaves either the old
outputs or the new ones, never an empty or truncated file (on file systems
that honour fsync; a folder that cannot be opened for it, as on some
network mounts, is skipped).

    check_folder(out, ["results.json", "report.html", "catalog/"], inputs=[req])
    ...work...
    write_folder(out, {"results.json": text, "catalog/stacks.toml": text2}, inputs=[req])
"""
from __future__ import annotations

import contextlib
import os
import shutil
import signal
import tempfile
import threading
from pathlib import Path
from typing import Callable, Iterable, Mapping, Union

from ..errors import HOLDING_SIGNALS, InputError, raise_if_interrupted

Content = Union[str, bytes, Callable[[], Union[str, bytes]]]
MAX_CARRIED = 200     # entries of an existing --out folder carried over; more means a wrong folder


def _umask() -> int:
    current = os.umask(0)
    os.umask(current)
    return current


def _same(a: Path, b: Path) -> bool:
    try:
        return os.path.samefile(a, b)
    except OSError:
        return os.path.abspath(a) == os.path.abspath(b)


def _inside(child: Path, parent: Path) -> bool:
    """``child`` is ``parent`` or lies somewhere below it."""
    try:
        child, parent = child.resolve(), parent.resolve()
    except (OSError, RuntimeError):
        return False
    return child == parent or parent in child.parents


def _writable_ancestor(path: Path, option: str) -> None:
    """The nearest existing ancestor of ``path`` must be a writable folder
    (the missing ones will be created there)."""
    parent = path.absolute().parent
    while True:
        try:
            exists = parent.exists()
        except OSError as exc:
            raise InputError(str(parent), option, f"cannot use this folder: {exc.strerror or exc}") from None
        if exists:
            break
        parent = parent.parent
    if not parent.is_dir():
        raise InputError(str(parent), option, "expected a folder, got a file")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise InputError(str(parent), option, "folder is not writable")


def _kind(path: Path) -> str | None:
    """'dir', 'file', 'other' or None (absent); a symlink loop is an error."""
    try:
        if path.is_dir():
            return "dir"
        if path.is_file():
            return "file"
        if path.is_symlink() or os.path.lexists(path):
            os.stat(path)      # raises on a loop or a dangling link
            return "other"
    except OSError as exc:
        raise InputError(str(path), None, f"cannot use this path: {exc.strerror or exc}") from None
    return None


def _not_an_input(path: Path, inputs: Iterable, option: str) -> None:
    for given in inputs or ():
        if given is not None and _same(path, Path(given)):
            raise InputError(str(path), option, "this is one of the command's inputs; refusing to overwrite it")


def check_folder(dest: str | Path, names: Iterable[str], inputs: Iterable = (), option: str = "--out") -> Path:
    """Check before any work that ``dest`` can receive the outputs ``names``
    (relative paths; a trailing "/" or a "sub/file" name means a subfolder)."""
    dest = Path(dest)
    kind = _kind(dest)
    if kind not in (None, "dir"):
        raise InputError(str(dest), option, "expected a folder, got a file")
    if kind is None:
        _writable_ancestor(dest, option)
    else:
        if not os.access(dest, os.W_OK | os.X_OK) or not os.access(dest.absolute().parent, os.W_OK | os.X_OK):
            raise InputError(str(dest), option, "folder is not writable (or its parent is not)")
        if _inside(Path.cwd(), dest):
            raise InputError(str(dest), option, "expected a folder other than the current one or above it")
        for name in names:
            top, _, below = name.partition("/")
            want = "dir" if below or name.endswith("/") else "file"
            have = _kind(dest / top)
            if have is not None and have != want:
                raise InputError(str(dest / top), option, f"expected {'a folder' if want == 'dir' else 'a file'} "
                                                          f"for the output {top!r}, found {'a folder' if have == 'dir' else 'a file'}")
    for given in inputs or ():
        if given is not None and _inside(Path(given), dest):
            raise InputError(str(dest), option, f"the folder holds the input {given}; choose another output folder")
    return dest


def check_files(paths: Iterable, inputs: Iterable = (), option: str = "--out") -> list[Path]:
    """Check before any work that each of ``paths`` can be written as a file."""
    checked = []
    for path in paths:
        path = Path(path)
        kind = _kind(path)
        if kind == "dir":
            raise InputError(str(path), option, "expected a file name, got a folder")
        if kind == "other":
            raise InputError(str(path), option, "expected a regular file")
        _not_an_input(path, inputs, option)
        if kind is None:
            _writable_ancestor(path, option)
        elif not os.access(path.absolute().parent, os.W_OK | os.X_OK):
            raise InputError(str(path.parent), option, "folder is not writable")
        checked.append(path)
    return checked


@contextlib.contextmanager
def signals_deferred():
    """Hold SIGINT and SIGTERM back for a few renames; they are delivered
    (KeyboardInterrupt, ...) right after the block."""
    if not hasattr(signal, "pthread_sigmask") or threading.current_thread() is not threading.main_thread():
        yield
        return
    HOLDING_SIGNALS.append(1)
    old = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT, signal.SIGTERM})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)
        HOLDING_SIGNALS.pop()
    raise_if_interrupted()          # one that came during the swap: the outputs are whole, the run was interrupted


def _render(content: Content) -> bytes:
    value = content() if callable(content) else content
    return value.encode("utf-8") if isinstance(value, str) else bytes(value)


def _write(path: Path, content: Content) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "wb") as handle:
        handle.write(_render(content))
        handle.flush()
        os.fsync(handle.fileno())
    os.chmod(path, 0o666 & ~_umask())


def fsync_folder(folder: Path) -> None:
    """Flush a folder's entries (names created, renamed or removed) to disk."""
    try:
        fd = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass            # a file system that cannot fsync a folder: nothing more to do
    finally:
        os.close(fd)


def _fsync_tree(root: Path) -> None:
    """Every folder below and including ``root`` (its files were fsynced as written)."""
    for folder, _, _ in os.walk(root):
        fsync_folder(Path(folder))


def _carry_over(old: Path, new: Path, outputs: set[str], option: str) -> None:
    """Hard-link the entries of ``old`` that are not outputs into ``new``."""
    others = [entry for entry in old.iterdir() if entry.name not in outputs]
    if len(others) > MAX_CARRIED:
        raise InputError(str(old), option, f"expected a folder for outputs, got one holding {len(others)} other entries")
    for entry in others:
        target = new / entry.name
        if entry.is_dir() and not entry.is_symlink():
            shutil.copytree(entry, target, symlinks=True, copy_function=_link_or_copy)
        else:
            _link_or_copy(entry, target)


def _link_or_copy(src, dst) -> None:
    try:
        os.link(src, dst, follow_symlinks=False)
    except OSError:
        shutil.copy2(src, dst, follow_symlinks=False)


@contextlib.contextmanager
def _os_errors(dest, option: str):
    """A failed write (read-only file system, disk full) is one line, exit 2."""
    try:
        yield
    except OSError as exc:
        raise InputError(str(dest), option, f"cannot write the outputs: {exc.strerror or exc}") from None


def write_folder(dest: str | Path, files: Mapping[str, Content], inputs: Iterable = (), option: str = "--out") -> Path:
    """Write ``files`` ({relative name: text, bytes or a callable giving
    them}) as the folder ``dest``, swapped in at once (module docstring)."""
    dest = check_folder(dest, list(files), inputs, option)
    with _os_errors(dest, option):
        return _write_folder(dest, files, option)


def _write_folder(dest: Path, files: Mapping[str, Content], option: str) -> Path:
    parent = dest.absolute().parent
    parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(dir=parent, prefix=f".{dest.name}.new-"))
    old = None
    try:
        for name, content in files.items():
            _write(tmp / name, content)
        os.chmod(tmp, 0o777 & ~_umask())
        if dest.is_dir():
            _carry_over(dest, tmp, {name.partition("/")[0] for name in files}, option)
            old = Path(tempfile.mkdtemp(dir=parent, prefix=f".{dest.name}.old-"))
            _fsync_tree(tmp)
            raise_if_interrupted()      # a signal swallowed on the way: write nothing
            with signals_deferred():
                os.replace(dest, old / dest.name)
                try:
                    os.replace(tmp, dest)
                except BaseException:
                    os.replace(old / dest.name, dest)
                    raise
                fsync_folder(parent)
        else:
            _fsync_tree(tmp)
            raise_if_interrupted()      # a signal swallowed on the way: write nothing
            with signals_deferred():
                os.replace(tmp, dest)
                fsync_folder(parent)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
        if old is not None:
            shutil.rmtree(old, ignore_errors=True)
    return dest


def write_files(files: Mapping, inputs: Iterable = (), option: str = "--out") -> list[Path]:
    """Write ``files`` ({path: content}) each over its path; all renames
    happen together with signals held back, undone if one fails."""
    paths = check_files(list(files), inputs, option)
    with _os_errors(paths[0] if paths else "", option):
        _write_files(paths, list(files.values()))
    return paths


def _write_files(paths: list[Path], contents: list) -> None:
    temps: dict[Path, Path] = {}
    backups: dict[Path, Path] = {}
    backup_folders: list[Path] = []
    done: list[Path] = []
    try:
        for path, content in zip(paths, contents):
            path.parent.mkdir(parents=True, exist_ok=True)
            fd, name = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
            os.close(fd)
            temps[path] = Path(name)
            _write(temps[path], content)
            if path.exists():
                # a private folder of its own: no other process can take the backup's name
                backup_folders.append(Path(tempfile.mkdtemp(dir=path.parent, prefix=f".{path.name}.", suffix=".old")))
                backups[path] = backup_folders[-1] / path.name
                _link_or_copy(path, backups[path])
        raise_if_interrupted()
        with signals_deferred():
            try:
                for path in paths:
                    os.replace(temps[path], path)
                    del temps[path]
                    done.append(path)
                for folder in {path.absolute().parent for path in paths}:
                    fsync_folder(folder)
            except BaseException:
                for path in done:
                    if path in backups:
                        os.replace(backups.pop(path), path)
                    else:
                        path.unlink(missing_ok=True)
                raise
    finally:
        for leftover in list(temps.values()) + list(backups.values()):
            leftover.unlink(missing_ok=True)
        for folder in backup_folders:
            shutil.rmtree(folder, ignore_errors=True)


def store_cache(target: Path, content: bytes, keep: int) -> None:
    """A cache file, renamed over ``target`` once written; only the ``keep``
    most recent files of its kind (suffix) stay in its folder. A cache that
    cannot be written is skipped: the next reader computes again."""
    tmp = None
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=target.parent, suffix=".tmp")
        with os.fdopen(fd, "wb") as handle:
            handle.write(content)
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(tmp, target)
        tmp = None
        kept = sorted(target.parent.glob(f"*{target.suffix}"), key=lambda f: f.stat().st_mtime, reverse=True)
        for old in kept[keep:]:
            old.unlink(missing_ok=True)
    except OSError:
        pass
    finally:
        if tmp is not None:
            Path(tmp).unlink(missing_ok=True)


@contextlib.contextmanager
def scratch_folder(files: Mapping[str, Content], prefix: str = "sizing-"):
    """A temporary folder holding ``files`` ({name: content}), removed after
    the block: a command reads back what it would write before writing it."""
    with tempfile.TemporaryDirectory(prefix=prefix) as tmp:
        for name, content in files.items():
            _write(Path(tmp) / name, content)
        yield Path(tmp)


def write_text(path: str | Path, text: str, inputs: Iterable = ()) -> None:
    """One file, atomically (``write_files`` with a single entry)."""
    write_files({Path(path): text}, inputs)
