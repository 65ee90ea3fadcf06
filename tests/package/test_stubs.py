"""The type stubs (python/stubs/fdhcert-stubs) against the module they describe: the same public
names, and for each function the same parameters in the same order with the same defaults, as
the module's own signatures (pybind11's docstrings) give them. FDHCERT_STUBS names the stub file
to check (an installed one); by default the source's."""
import ast
import os
import re
from pathlib import Path

import fdhcert

STUBS = Path(os.environ.get("FDHCERT_STUBS") or
             Path(__file__).resolve().parents[2] / "python/stubs/fdhcert-stubs/__init__.pyi")


def stub_tree():
    return ast.parse(STUBS.read_text(), filename=str(STUBS))


def public(names):
    return {n for n in names if not n.startswith("_")}


def stub_functions():
    return {node.name: node for node in stub_tree().body if isinstance(node, ast.FunctionDef)}


def module_parameters(function):
    """[(name, default source or None)] from pybind11's signature line "f(a: T, b: T = d) -> R"."""
    first = function.__doc__.splitlines()[0]
    inside = first[first.index("(") + 1:first.rindex(")")]
    parameters = []
    for part in re.split(r",\s*(?![^\[\]()]*[\])])", inside) if inside else []:
        name, _, rest = part.partition(":")
        default = rest.split("=", 1)[1].strip() if "=" in rest else None
        parameters.append((name.strip(), default))
    return parameters


def stub_parameters(node):
    args = node.args.args
    defaults = [None] * (len(args) - len(node.args.defaults)) + node.args.defaults
    return [(a.arg, None if d is None else ast.unparse(d)) for a, d in zip(args, defaults)]


def same_default(module_default, stub_default):
    if module_default is None or stub_default is None:
        return module_default == stub_default
    return ast.literal_eval(module_default) == ast.literal_eval(stub_default)


def test_the_stubs_name_every_public_name_of_the_module_and_no_other():
    stubbed = public(n.name for n in stub_tree().body
                     if isinstance(n, (ast.FunctionDef, ast.ClassDef)))
    assert stubbed == public(dir(fdhcert))


def test_each_function_has_the_modules_parameters_and_defaults():
    for name, node in stub_functions().items():
        module = module_parameters(getattr(fdhcert, name))
        stub = stub_parameters(node)
        assert [n for n, _ in stub] == [n for n, _ in module], name
        for (parameter, m), (_, s) in zip(module, stub):
            assert same_default(m, s), f"{name}({parameter}): module {m}, stub {s}"


def test_no_function_returns_an_untyped_dict():
    """Every dict the module returns has a TypedDict of its keys: no Any anywhere."""
    for name, node in stub_functions().items():
        assert "Any" not in ast.unparse(node.returns), name
    assert not any(isinstance(n, ast.ImportFrom) and any(a.name == "Any" for a in n.names)
                   for n in stub_tree().body)


def test_input_error_is_a_value_error_in_both():
    node = next(n for n in stub_tree().body if isinstance(n, ast.ClassDef))
    assert [ast.unparse(b) for b in node.bases] == ["ValueError"]
    assert issubclass(fdhcert.InputError, ValueError)
