"""``python -m sigdt``: the ``sigdt`` command line (see :mod:`sigdt._cli`)."""

from ._cli import main

if __name__ == "__main__":
    raise SystemExit(main())
