"""The type stubs (dcel/_dcel.pyi) cover every name the extension exports,
with the same parameters, and every public function and method has a
docstring."""
import ast
import inspect
import os
import re

import dcel
from dcel import _dcel

STUBS = os.path.join(os.path.dirname(dcel.__file__), "_dcel.pyi")


def stub_tree():
    with open(STUBS, encoding="utf-8") as f:
        return ast.parse(f.read())


def stubbed():
    """{name: [parameter names]} for functions, {Dcel.member: ...} for the class."""
    out = {}
    for node in stub_tree().body:
        if isinstance(node, ast.FunctionDef):
            out.setdefault(node.name, set()).update(a.arg for a in node.args.args + node.args.kwonlyargs)
        elif isinstance(node, ast.ClassDef):
            out[node.name] = set()
            for item in node.body:
                if isinstance(item, ast.FunctionDef):
                    out.setdefault(f"{node.name}.{item.name}", set()).update(
                        a.arg for a in item.args.args + item.args.kwonlyargs if a.arg != "self")
        elif isinstance(node, ast.AnnAssign):
            out[node.target.id] = set()
    return out


def runtime_parameters(obj):
    """Parameter names from pybind11's signature line, e.g. 'build(vertices: object, ...)'."""
    first = (obj.__doc__ or "").splitlines()[0]
    inside = first[first.index("(") + 1:first.rindex(")")] if "(" in first else ""
    names = set(re.findall(r"(?:^|,\s*)\*?(\w+)(?=:|=|,|$)", inside))
    return names - {"self", "*"}


def test_every_exported_name_is_stubbed_with_its_parameters():
    stubs = stubbed()
    for name, obj in vars(_dcel).items():
        if name.startswith("__"):
            continue
        assert name in stubs, f"_dcel.{name} has no stub"
        if callable(obj) and not isinstance(obj, type):
            assert runtime_parameters(obj) <= stubs[name], (name, runtime_parameters(obj), stubs[name])
    for name, member in vars(_dcel.Dcel).items():
        if name.startswith("_") and name not in ("__copy__", "__deepcopy__"):
            continue
        key = f"Dcel.{name}"
        assert key in stubs, f"Dcel.{name} has no stub"
        if callable(member):
            assert runtime_parameters(member) <= stubs[key], (key, runtime_parameters(member), stubs[key])


def test_every_public_name_has_a_docstring():
    for name in dcel.__all__:
        obj = getattr(dcel, name)
        if callable(obj):
            assert inspect.getdoc(obj), name
    for name, member in vars(_dcel.Dcel).items():
        if not name.startswith("_"):
            doc = member.__doc__ if not isinstance(member, property) else member.fget.__doc__ or member.__doc__
            assert doc and len(doc.strip()) > 10, f"Dcel.{name}"


def test_the_module_doctest_runs():
    import doctest

    failures, tried = doctest.testmod(dcel, verbose=False)
    assert tried > 0 and failures == 0
