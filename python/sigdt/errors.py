"""The exceptions and the warning sigdt raises (shapely's pattern: one base class).

Every exception sigdt raises on purpose is a :class:`SigdtError`; each also derives from the
built-in class a caller would expect (``ValueError`` for bad input, ``RuntimeError`` for a
bug), so ``except ValueError`` keeps working.

>>> import sigdt
>>> try:
...     sigdt.reconstruct([[0, 0], [1, float("nan")]])
... except sigdt.SigdtError as e:
...     print(type(e).__name__, isinstance(e, ValueError))
InvalidInputError True
"""

from __future__ import annotations

__all__ = ["InternalError", "InvalidInputError", "ParseError", "SigdtError", "SigdtWarning"]


class SigdtError(Exception):
    """The base class of every exception sigdt raises on purpose."""


class InvalidInputError(SigdtError, ValueError):
    """The points are unusable: wrong shape, non-finite values, or an impossible range."""


class ParseError(SigdtError, ValueError):
    """A point file could not be parsed; the message names the file and line."""


class InternalError(SigdtError, RuntimeError):
    """A bug inside sigdt (a Rust panic), reported instead of crashing."""


class SigdtWarning(UserWarning):
    """The result is not a faithful curve: the status is ``"sculpting-stuck"``,
    ``"branching"``, ``"noisy"``, ``"crossing"`` or ``"unfinished"`` (see
    :attr:`sigdt.Reconstruction.status`)."""
