"""Docstrings and stubs: numpydoc sections on every public function, and ``_core.pyi``
mirroring the extension module exactly (names, parameters, defaults).

README's Python section and the docstring examples themselves run as doctests
(``--doctest-modules --doctest-glob=*.md`` and ``testpaths`` in pyproject.toml).
"""

from __future__ import annotations

import ast
import inspect
import re
from pathlib import Path

import pytest
import sigdt
from sigdt import _core

STUB = Path(sigdt.__file__).with_name("_core.pyi")
FUNCTION_SECTIONS = ("Parameters", "Returns", "Raises", "Examples")


def _sections(doc: str) -> set[str]:
    """numpydoc section titles: a line followed by an underline of dashes as long."""
    lines = inspect.cleandoc(doc).splitlines()
    return {
        a.strip()
        for a, b in zip(lines, lines[1:])
        if b.strip() and set(b.strip()) == {"-"} and len(b.strip()) == len(a.strip())
    }


PUBLIC_FUNCTIONS = [n for n in sigdt.__all__ if inspect.isfunction(getattr(sigdt, n))]


def test_the_public_functions_are_the_expected_ones():
    assert sorted(PUBLIC_FUNCTIONS) == [
        "evaluate",
        "from_shapely",
        "graph_epsilon",
        "graph_overlap",
        "outlines",
        "plot_steps",
        "proximity_graph",
        "read_points",
        "reconstruct",
        "reconstruct_frame",
        "reconstruct_many",
        "to_shapely",
        "trace",
    ]


@pytest.mark.parametrize("name", PUBLIC_FUNCTIONS)
def test_public_function_has_numpydoc_sections(name):
    doc = inspect.getdoc(getattr(sigdt, name))
    assert doc, f"sigdt.{name} has no docstring"
    summary = doc.splitlines()[0]
    assert summary.endswith(".") and len(summary) <= 100, f"summary of {name}: {summary!r}"
    missing = [s for s in FUNCTION_SECTIONS if s not in _sections(doc)]
    assert not missing, f"sigdt.{name} lacks numpydoc sections {missing}"
    examples = doc.split("Examples\n--------", 1)[1]
    assert ">>> " in examples, f"sigdt.{name}'s Examples has no doctest"


@pytest.mark.parametrize("name", PUBLIC_FUNCTIONS)
def test_documented_parameters_match_the_signature(name):
    function = getattr(sigdt, name)
    doc = inspect.getdoc(function)
    assert "Parameters\n----------" in doc, f"sigdt.{name} has no Parameters section"
    block = doc.split("Parameters\n----------", 1)[1].split("\n\n")[0]
    documented = set()
    for line in block.splitlines():
        if line and not line.startswith(" "):
            documented.update(n.strip() for n in line.split(":")[0].split(","))
    assert documented == set(inspect.signature(function).parameters)


@pytest.mark.parametrize("name", [n for n in sigdt.__all__ if inspect.isclass(getattr(sigdt, n))])
def test_public_classes_have_docstrings(name):
    assert inspect.getdoc(getattr(sigdt, name)), f"sigdt.{name} has no docstring"


def test_reconstruction_members_are_documented():
    cls = sigdt.Reconstruction
    attributes = _attribute_names(inspect.getdoc(cls))
    for name, member in vars(cls).items():
        if name.startswith("_"):
            continue
        if inspect.isfunction(member):
            assert inspect.getdoc(member), f"Reconstruction.{name} has no docstring"
        elif isinstance(member, property):
            assert member.__doc__ or name in attributes, f"Reconstruction.{name} undocumented"
    for name in cls.__slots__:
        if not name.startswith("_"):
            assert name in attributes, f"Reconstruction.{name} is not in Attributes"


def _attribute_names(doc: str) -> set[str]:
    block = doc.split("Attributes\n----------", 1)[1]
    return {m.group(1) for m in re.finditer(r"^(\w+) :", block, re.MULTILINE)}


def test_readme_python_section_is_a_collected_doctest(repo_root):
    readme = (repo_root / "README.md").read_text()
    assert re.search(r"^>>> import .*sigdt", readme, re.MULTILINE)
    config = (repo_root / "pyproject.toml").read_text()
    # Collected: README.md and the docs with Python examples are test paths, and the glob
    # makes their ``>>>`` blocks doctests.
    assert "--doctest-glob=*.md" in config and "--doctest-modules" in config
    testpaths = re.search(r"^testpaths = \[(.*)\]", config, re.MULTILINE).group(1)
    for doc in ["README.md", "docs/steps.md", "docs/python.md"]:
        assert f'"{doc}"' in testpaths, f"{doc} is not collected"


# --- the stub ------------------------------------------------------------------------------------


def _stub() -> ast.Module:
    return ast.parse(STUB.read_text())


def _stub_functions() -> dict[str, ast.FunctionDef]:
    return {n.name: n for n in _stub().body if isinstance(n, ast.FunctionDef)}


def _core_functions() -> dict[str, object]:
    return {
        name: f
        for name, f in vars(_core).items()
        if callable(f) and not inspect.isclass(f) and not name.startswith("_")
    }


def test_stub_and_extension_define_the_same_functions():
    assert set(_stub_functions()) == set(_core_functions())


def test_stub_parameters_match_the_extension():
    stubs = _stub_functions()
    for name, function in _core_functions().items():
        runtime = inspect.signature(function).parameters  # from PyO3's __text_signature__
        args = stubs[name].args
        positional = args.posonlyargs + args.args
        stub_names = [a.arg for a in positional + args.kwonlyargs]
        assert stub_names == list(runtime), f"{name}: stub {stub_names} vs {list(runtime)}"
        with_default = [a.arg for a in positional[len(positional) - len(args.defaults) :]]
        with_default += [a.arg for a, d in zip(args.kwonlyargs, args.kw_defaults) if d]
        runtime_default = [p for p, v in runtime.items() if v.default is not v.empty]
        assert with_default == runtime_default, f"{name}: defaults differ"
        for arg, default in zip(positional[len(positional) - len(args.defaults) :], args.defaults):
            assert ast.literal_eval(default) == runtime[arg.arg].default, f"{name}({arg.arg})"


def test_stub_and_extension_define_the_same_names():
    stub_names = set()
    for node in _stub().body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            stub_names.add(node.name)
        elif (
            isinstance(node, ast.AnnAssign)
            and not node.target.id.startswith("_")
            or isinstance(node, ast.AnnAssign)
            and node.target.id == "__version__"
        ):
            stub_names.add(node.target.id)
    runtime = {n for n in vars(_core) if not n.startswith("_")} | {"__version__"}
    assert stub_names == runtime


def test_stub_classes_have_the_runtime_bases():
    for node in _stub().body:
        if isinstance(node, ast.ClassDef):
            bases = [b.id for b in node.bases]
            runtime = getattr(_core, node.name)
            assert [b.__name__ for b in runtime.__bases__] == bases, node.name


def test_stub_classes_have_the_runtime_members():
    # Properties in the stub are getters at runtime, methods are methods with the same
    # parameters; the exceptions have no public members.
    for node in _stub().body:
        if not isinstance(node, ast.ClassDef):
            continue
        runtime = getattr(_core, node.name)
        members = {n: v for n, v in vars(runtime).items() if not n.startswith("_")}
        stub = {n.name: n for n in node.body if isinstance(n, ast.FunctionDef)}
        assert set(stub) == set(members), node.name
        for name, definition in stub.items():
            is_property = any(
                getattr(d, "id", None) == "property" for d in definition.decorator_list
            )
            member = members[name]
            assert is_property == inspect.isgetsetdescriptor(member), f"{node.name}.{name}"
            if not is_property:
                stub_args = [a.arg for a in definition.args.args[1:]]
                runtime_args = list(inspect.signature(member).parameters)[1:]
                assert stub_args == runtime_args, f"{node.name}.{name}"
