"""The project's import graph, read statically (ast) from the source tree: module → the
project modules it imports (at any depth of the file, lazy imports included)."""
from __future__ import annotations

import ast
from functools import cache
from pathlib import Path
from types import MappingProxyType
from typing import Mapping

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ("polygons", "diagrams")


def module_files() -> dict[str, Path]:
    return dict(_module_files())


@cache
def _module_files() -> dict[str, Path]:
    out = {}
    for pkg in PACKAGES:
        for f in sorted((ROOT / pkg).rglob("*.py")):
            parts = list(f.relative_to(ROOT).with_suffix("").parts)
            if parts[-1] == "__init__":
                parts = parts[:-1]
            out[".".join(parts)] = f
    return out


def _resolve(mod: str, is_pkg: bool, node: ast.ImportFrom, known) -> list[str]:
    if node.level == 0:
        base = node.module or ""
    else:
        parts = mod.split(".")
        if not is_pkg:
            parts = parts[:-1]
        parts = parts[:len(parts) - (node.level - 1)]
        base = ".".join(parts + ([node.module] if node.module else []))
    names = []
    for a in node.names:
        cand = f"{base}.{a.name}" if base else a.name
        names.append(cand if cand in known else base)
    return names


@cache
def tree(path: Path) -> ast.Module:
    """The parsed source of ``path``, read once per test process (the layer tests walk every
    module's tree several times; nothing here changes a tree)."""
    return ast.parse(path.read_text(encoding="utf-8"))


@cache
def nodes(path: Path) -> tuple[ast.AST, ...]:
    """Every node of :func:`tree` (``ast.walk`` order), once per test process."""
    return tuple(ast.walk(tree(path)))


def imports(top_level_only: bool = False) -> dict[str, set[str]]:
    """module → every name it imports (project modules resolved, others as written).
    ``top_level_only``: only the imports executed when the module is imported.
    (A fresh copy each call of the graph read once per test process.)"""
    return {m: set(n) for m, n in graph(top_level_only).items()}


@cache
def graph(top_level_only: bool = False) -> Mapping[str, frozenset[str]]:
    """:func:`imports` read once per test process, read-only (no copy)."""
    return MappingProxyType(_imports(top_level_only))


def _imports(top_level_only: bool) -> dict[str, frozenset[str]]:
    files = _module_files()
    graph: dict[str, frozenset[str]] = {}
    for mod, f in files.items():
        tree_ = tree(f)
        is_pkg = f.name == "__init__.py"
        found: set[str] = set()
        for node in (tree_.body if top_level_only else nodes(f)):
            if isinstance(node, ast.Import):
                found.update(a.name for a in node.names)
            elif isinstance(node, ast.ImportFrom):
                found.update(_resolve(mod, is_pkg, node, files))
        graph[mod] = frozenset(found)
    return graph


def closure(graph: dict[str, set[str]], start: str) -> set[str]:
    seen, todo = set(), [start]
    while todo:
        m = todo.pop()
        if m in seen:
            continue
        seen.add(m)
        todo.extend(n for n in graph.get(m, ()) if n in graph)
    return seen
