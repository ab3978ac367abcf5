"""The ``sigdt`` command line from Python: the package's ``sigdt`` script and ``python -m sigdt``.

Both run the ``sigdt`` binary that the wheel carries (``sigdt/_bin/sigdt``, the one cargo
builds from ``crates/sigdt-cli``), so they take the same arguments, print the same output and
exit with the same statuses. On POSIX systems the binary replaces the Python process, so
signals and exit statuses are its own.
"""

from __future__ import annotations

import os
import subprocess
import sys
from collections.abc import Sequence
from pathlib import Path

#: Where the wheel puts the command line (``make py-build`` and ``make wheel`` copy it there).
BINARY = Path(__file__).parent / "_bin" / ("sigdt.exe" if os.name == "nt" else "sigdt")


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line with ``argv`` (default: ``sys.argv[1:]``).

    On POSIX systems the process becomes the ``sigdt`` binary and this does not return;
    elsewhere it returns the binary's exit status.
    """
    args = ["sigdt", *(sys.argv[1:] if argv is None else argv)]
    if not BINARY.is_file():
        print(
            f"sigdt: the command line is missing from this installation ({BINARY}): install "
            "a wheel, or build it from the repository with `make py-build`",
            file=sys.stderr,
        )
        return 1
    sys.stdout.flush()
    sys.stderr.flush()
    if os.name == "posix":
        os.execv(BINARY, args)
    return subprocess.call([str(BINARY), *args[1:]])
