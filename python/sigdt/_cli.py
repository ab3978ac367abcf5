"""The ``sigdt`` command line from Python: the package's ``sigdt`` script and ``python -m sigdt``.

Both run the same Rust command line as the ``sigdt`` binary built by cargo (it is compiled into
the extension), so they take the same arguments, print the same output and exit with the same
statuses. ``sigdt bench`` starts its workers as ``python -m sigdt`` with this interpreter.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence

from . import _core


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line with ``argv`` (default: ``sys.argv[1:]``) and return its exit status.

    A usage error or an interrupt ends the process from inside, as the binary does.
    """
    args = list(sys.argv[1:] if argv is None else argv)
    return int(_core.cli_main(["sigdt", *args], [sys.executable, "-m", "sigdt"]))
