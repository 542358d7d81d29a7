"""One validated reader for the text files the physics layer reads: lab exports, lab manifests, measurements.

Every refusal is a :class:`~vibration.physics.model.ParameterError` naming the file and what is
allowed: not a path, missing or unreadable, not a regular file, larger than the caller's limit,
or not UTF-8 (a byte-order mark is dropped).
"""

from __future__ import annotations

import os
from pathlib import Path

from .model import ParameterError

__all__ = ["read_text_file"]


def read_text_file(path, kind: str, *, max_bytes: int, label: str | None = None) -> tuple[str, str]:
    """The name and the text of a UTF-8 file of at most ``max_bytes`` bytes.

    Parameters
    ----------
    path : str or os.PathLike
        The file.
    kind : str
        What the file should be, for the messages ("logger CSV file", ...).
    max_bytes : int
        Largest size accepted, bytes.
    label : str, optional
        The name the messages and the result give the file (default ``str(path)``).

    Returns
    -------
    tuple of str
        ``(name, text)``, the text without a byte-order mark.

    Raises
    ------
    ParameterError
        When ``path`` is not a path, cannot be read, is not a file, is larger than ``max_bytes``
        or is not UTF-8.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = pathlib.Path(d) / "a.csv"
    ...     _ = p.write_bytes("\\ufefft_s\\n0.0\\n".encode("utf-8"))
    ...     name, text = read_text_file(p, "CSV file", max_bytes=100, label="a.csv")
    >>> name, text
    ('a.csv', 't_s\\n0.0\\n')
    >>> read_text_file(3, "CSV file", max_bytes=100)
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: path = 3 is not a path: allowed str or os.PathLike
    """
    if isinstance(path, bytes) or not isinstance(path, (str, os.PathLike)):
        raise ParameterError(f"path = {path!r:.80} is not a path: allowed str or os.PathLike")
    p = Path(path)
    name = str(p) if label is None else label
    try:
        size = p.stat().st_size
    except OSError as exc:
        raise ParameterError(
            f"path = {name!r} cannot be read: {exc.strerror or exc}: allowed an existing, readable {kind}"
        ) from None
    if not p.is_file():
        raise ParameterError(f"path = {name!r} is not a file: allowed a {kind}")
    if size > max_bytes:
        raise ParameterError(f"path = {name!r} has {size} bytes: allowed at most {max_bytes} bytes")
    try:
        return name, p.read_bytes().decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise ParameterError(f"file {name!r} is not UTF-8 (byte {exc.start}): allowed UTF-8 text") from None
