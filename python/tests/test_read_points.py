"""``sigdt.read_points``: every input format, parse errors naming file and line, I/O errors."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
import sigdt

FILES = {
    "comments.xy": (
        "# a comment\nx y\n0 0\n1.5 2 # trailing\n\n-3e2\t4\n",
        [[0, 0], [1.5, 2], [-300, 4]],
    ),
    "points.csv": ("x,y\n0,0\n1.5,2\n", [[0, 0], [1.5, 2]]),
    "dey.gtn": ("3 2 0 0\n0 0.0 0.0\n1 1.0 0.5\n2 2 3\n", [[0, 0], [1, 0.5], [2, 3]]),
    "windows.txt": ("x\ty\r\n1\t2\r\n3 4\r\n", [[1, 2], [3, 4]]),
    "no-final-newline.p2d": ("1 2\n3 4", [[1, 2], [3, 4]]),
    "empty.xy": ("", np.empty((0, 2))),
}


@pytest.mark.parametrize("name", sorted(FILES))
def test_read_points_formats(tmp_path, name):
    text, expected = FILES[name]
    path = tmp_path / name
    path.write_bytes(text.encode())
    for given in (path, str(path)):
        points = sigdt.read_points(given)
        assert points.dtype == np.float64 and points.flags.c_contiguous
        assert np.array_equal(points, np.asarray(expected, dtype=np.float64).reshape(-1, 2))


@pytest.mark.parametrize(
    ("text", "line", "message"),
    [
        ("0 0\n1 abc\n", 2, "'abc' is not a number"),
        ("0 0\n1 0\n1 2 3\n", 3, "expected 2 numbers"),
        ("# c\n0 0\nnan 1\n", 3, "coordinate 'nan' is not finite"),
    ],
)
def test_read_points_parse_error_names_file_and_line(tmp_path, text, line, message):
    path = tmp_path / "bad.xy"
    path.write_bytes(text.encode())
    with pytest.raises(sigdt.ParseError, match=re.escape(f"{path}:{line}: ") + message):
        sigdt.read_points(path)


def test_read_points_missing_file_is_file_not_found(tmp_path):
    missing = tmp_path / "missing.xy"
    with pytest.raises(FileNotFoundError, match=re.escape(str(missing))) as caught:
        sigdt.read_points(missing)
    # As open() raises it: errno, the reason and the file name.
    assert caught.value.errno == 2 and caught.value.filename == str(missing)
    assert str(caught.value) == f"[Errno 2] No such file or directory: '{missing}'"
    with pytest.raises(IsADirectoryError):
        sigdt.read_points(tmp_path)  # a directory


def test_read_points_then_reconstruct_bundled_input(repo_root: Path):
    points = sigdt.read_points(repo_root / "data/inputs/glyph_n_tilde.xy")
    expected = np.loadtxt(repo_root / "data/inputs/glyph_n_tilde.gt", dtype=np.int64)
    assert np.array_equal(points, np.loadtxt(repo_root / "data/inputs/glyph_n_tilde.xy"))
    assert np.array_equal(sigdt.reconstruct(points).edges, expected)


def test_read_points_reads_every_format_the_cli_reads(tmp_path):
    # Issue 30, G10: `.npy` and `.gz` failed as "NUL bytes: UTF-16?", WKT and tables too.
    import gzip

    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    np.save(tmp_path / "sq.npy", square)
    with gzip.open(tmp_path / "sq.xy.gz", "wt") as f:
        f.write("".join(f"{x} {y}\n" for x, y in square))
    (tmp_path / "sq.wkt").write_text("MULTIPOINT ((0 0), (1 0), (1 1), (0 1))")
    (tmp_path / "sq.geojson").write_text(
        '{"type": "MultiPoint", "coordinates": [[0, 0], [1, 0], [1, 1], [0, 1]]}'
    )
    (tmp_path / "sq.csv").write_text("id;name;x;y\n1;a;0;0\n2;b;1;0\n3;c;1;1\n4;d;0;1\n")
    for name in ("sq.npy", "sq.xy.gz", "sq.wkt", "sq.geojson", "sq.csv"):
        np.testing.assert_array_equal(sigdt.read_points(tmp_path / name), square, name)
    (tmp_path / "t.csv").write_text("p1,0,0\np2,1,0\np3,1,1\np4,0,1\n")
    np.testing.assert_array_equal(sigdt.read_points(tmp_path / "t.csv", columns="2,3"), square)
    with pytest.raises(ValueError, match="sq.wkt is WKT, which has no columns"):
        sigdt.read_points(tmp_path / "sq.wkt", columns="1,2")
    with pytest.raises(sigdt.ParseError, match="more than 3 points"):
        sigdt.read_points(tmp_path / "sq.npy", max_points=3)
