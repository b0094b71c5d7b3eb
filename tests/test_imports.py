"""The package's imports form no circle: every ``import`` of a valvetrain module, at the top of a file or inside a
function, read from the source with the standard library's parser (an independent reading of the import graph, not
the interpreter's, which forgives a circle broken by a late import)."""

import ast
from pathlib import Path

import valvetrain

ROOT = Path(valvetrain.__file__).parent


def _module(path):
    parts = list(path.relative_to(ROOT.parent).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imports(path, name):
    """The valvetrain modules one file imports (a name taken from a package counts as its submodule if there is
    one)."""
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    out = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            out |= {a.name for a in node.names if a.name.startswith("valvetrain")}
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[:len(package.split(".")) - node.level + 1]
                source = ".".join(base + ([node.module] if node.module else []))
            else:
                source = node.module or ""
            if source.startswith("valvetrain"):
                out.add(source)
                out |= {f"{source}.{a.name}" for a in node.names}
    return out


def graph():
    """Module -> the valvetrain modules it imports (only modules that exist)."""
    files = {_module(p): p for p in ROOT.rglob("*.py")}
    return {name: {m for m in _imports(path, name) if m in files and m != name} for name, path in files.items()}


def circles(edges):
    """The strongly connected groups of more than one module (Tarjan)."""
    index, low, stack, on, found, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in edges[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            group = set()
            while True:
                w = stack.pop()
                on.discard(w)
                group.add(w)
                if w == v:
                    break
            if len(group) > 1:
                found.append(sorted(group))

    for v in sorted(edges):
        if v not in index:
            visit(v)
    return found


def test_the_circle_finder_finds_a_circle():
    """A two-module circle (the one specification/models.py and validate.py had) is found; a chain is not."""
    assert circles({"a": {"b"}, "b": {"a"}, "c": {"a"}}) == [["a", "b"]]
    assert circles({"a": {"b"}, "b": set()}) == []


def test_the_package_has_no_import_circle():
    edges = graph()
    assert "valvetrain.specification.validate" in edges["valvetrain.specification.models"]
    packages = {name.rpartition(".")[0] for name in edges}
    # a package's __init__ re-exports its submodules; the circle through it is not a circle of the code
    own = {v: {w for w in ws if not (w in packages and v.startswith(w + "."))} for v, ws in edges.items()}
    assert circles(own) == []
