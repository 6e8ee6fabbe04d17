"""The package's layout stays as documented: every module in docs/architecture.md's table,
no import cycles at module level, no new ones anywhere, no new private names shared.

Issue 30 ("One house") asks for these guards. The import graph is read with ``ast``, never
by importing: an edge A → B for every ``import dynsolve.B`` / ``from dynsolve.B import x``
in A (``from dynsolve.P import M`` where ``P/M.py`` exists is an edge to the module M).
Imports under ``if TYPE_CHECKING:`` never run and are left out. The parent packages that
Python initialises on the way (``dynsolve/P/__init__.py``) are not counted as edges.
"""

from __future__ import annotations

import ast
import functools
import re
from collections.abc import Iterator
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "dynsolve"
ARCHITECTURE = ROOT / "docs" / "architecture.md"

# Import cycles that exist only through imports placed inside functions (issue 30 counted
# 13; 12 groups of modules remained when this test was written). The ceiling is the number
# of import edges that lie on a cycle (A imports B and B, perhaps through others, imports
# A). It can only go down: lower it when a refactor breaks a cycle; never raise it.
CYCLIC_EDGES_CEILING = 39

# Private names (``_name``) imported from another module (issue 30: "no private name
# imported across modules"). The list can only shrink: when a helper is made public (or
# moved), delete its entry; never add one. Entries are (importing module, module, name).
PRIVATE_IMPORTS_ALLOWED = {
    ("dynsolve.linkage.problem", "dynsolve.modes.scene_mode", "_row"),
    ("dynsolve.linkage.problem", "dynsolve.modes.scene_mode", "_unit"),
    ("dynsolve.linkage.problem", "dynsolve.modes.scene_mode", "_unused"),
    ("dynsolve.modes.oneline_events", "dynsolve.principles.rectilinear", "_sign"),
    ("dynsolve.rigid3d.energy", "dynsolve.modes.scene_mode", "_row"),
    ("dynsolve.rigid3d.energy", "dynsolve.modes.scene_mode", "_unit"),
    ("dynsolve.rigid3d.energy", "dynsolve.modes.scene_mode", "_unused"),
    ("dynsolve.rigid3d.energy", "dynsolve.rigid3d.problem", "_inertia_note"),
    ("dynsolve.rigid3d.problem", "dynsolve.modes.scene_mode", "_row"),
    ("dynsolve.rigid3d.problem", "dynsolve.modes.scene_mode", "_unit"),
    ("dynsolve.rigid3d.problem", "dynsolve.modes.scene_mode", "_unused"),
    ("dynsolve.simulate.circle", "dynsolve.principles.until", "_circle"),
    ("dynsolve.simulate.contact", "dynsolve.principles.until", "_circle_of"),
    ("dynsolve.simulate.contact", "dynsolve.simulate.equations", "_applied"),
    ("dynsolve.simulate.contact", "dynsolve.simulate.equations", "_build"),
    ("dynsolve.solver.elimination", "dynsolve.solver.blocks", "_univariate_roots"),
    ("dynsolve.stage_finds", "dynsolve.modes.scene_mode", "_body"),
}

Graph = dict[str, set[str]]


def _modules() -> dict[str, Path]:
    """Every module of the package by dotted name (a package by its ``__init__.py``)."""
    modules = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = list(path.relative_to(ROOT).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        modules[".".join(parts)] = path
    return modules


MODULES = _modules()


def _is_type_checking(node: ast.If) -> bool:
    test = node.test
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


def _imports(node: ast.AST, where: str = "module") -> Iterator[tuple[ast.stmt, str]]:
    """Every import statement under ``node`` with where it runs: "module" (on import, class
    bodies included), "function" (when a function is called) or "typing" (never)."""
    for child in ast.iter_child_nodes(node):
        if isinstance(child, ast.Import | ast.ImportFrom):
            yield child, where
        elif isinstance(child, ast.If) and _is_type_checking(child):
            for stmt in child.body:
                yield from _imports(ast.Module(body=[stmt], type_ignores=[]), "typing")
            for stmt in child.orelse:
                yield from _imports(ast.Module(body=[stmt], type_ignores=[]), where)
        elif isinstance(child, ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda):
            yield from _imports(child, "function")
        else:
            yield from _imports(child, where)


def _owner(name: str) -> str | None:
    """The package's module that ``name`` (a module or a name in one) lives in."""
    while name not in MODULES and "." in name:
        name = name.rpartition(".")[0]
    return name if name in MODULES else None


@functools.cache
def _scan() -> tuple[Graph, Graph, set[tuple[str, str, str]]]:
    """The module-level and function-level import graphs, and the private names imported
    from another module."""
    graphs: dict[str, Graph] = {"module": {}, "function": {}, "typing": {}}
    private: set[tuple[str, str, str]] = set()
    for name, path in MODULES.items():
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        for node, where in _imports(ast.parse(path.read_text(), str(path))):
            targets = []
            if isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            else:
                base = node.module or ""
                if node.level:
                    parts = package.split(".")[: len(package.split(".")) - node.level + 1]
                    base = ".".join([*parts, *([node.module] if node.module else [])])
                for alias in node.names:
                    sub = f"{base}.{alias.name}"
                    targets.append(sub if sub in MODULES else base)
                    is_private = alias.name.startswith("_") and not alias.name.startswith("__")
                    if is_private and sub not in MODULES and _owner(base) not in (None, name):
                        private.add((name, base, alias.name))
            for target in targets:
                owner = _owner(target) if target.startswith("dynsolve") else None
                if owner is not None and owner != name:
                    graphs[where].setdefault(name, set()).add(owner)
    return graphs["module"], graphs["function"], private


def _cycles(graph: Graph) -> list[list[str]]:
    """The groups of modules that import each other in a ring (strongly connected
    components of more than one module), by Tarjan's algorithm, iteratively."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    groups: list[list[str]] = []
    for start in sorted(MODULES):
        if start in index:
            continue
        work = [(start, iter(sorted(graph.get(start, ()))))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, successors = work[-1]
            step = next(successors, None)
            if step is not None:
                if step not in index:
                    index[step] = low[step] = len(index)
                    stack.append(step)
                    on_stack.add(step)
                    work.append((step, iter(sorted(graph.get(step, ())))))
                elif step in on_stack:
                    low[node] = min(low[node], index[step])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                group = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    group.append(member)
                    if member == node:
                        break
                if len(group) > 1:
                    groups.append(sorted(group))
    return groups


def _union(*graphs: Graph) -> Graph:
    merged: Graph = {}
    for graph in graphs:
        for source, targets in graph.items():
            merged.setdefault(source, set()).update(targets)
    return merged


def _documented() -> set[str]:
    """The paths (relative to dynsolve/) in the first column of architecture.md's tables."""
    rows = re.findall(r"^\|\s*`([^`]+)`", ARCHITECTURE.read_text(), re.M)
    return set(rows)


def _first_line(path: Path) -> str | None:
    doc = ast.get_docstring(ast.parse(path.read_text(), str(path)))
    return doc.strip().splitlines()[0] if doc and doc.strip() else None


def test_every_module_is_in_the_architecture_table() -> None:
    documented = _documented()
    missing = sorted(
        str(path.relative_to(PACKAGE))
        for path in MODULES.values()
        if str(path.relative_to(PACKAGE)) not in documented
    )
    rows = "\n".join(f"| `{m}` | {_first_line(PACKAGE / m) or '(no docstring)'} |" for m in missing)
    where = "docs/architecture.md (each in the table of the stage it serves)"
    assert not missing, f"add these rows to {where}:\n{rows}"


def test_every_module_in_the_table_exists() -> None:
    gone = sorted(m for m in _documented() if not (PACKAGE / m).is_file())
    assert not gone, f"docs/architecture.md names modules that do not exist: {gone}"


def test_the_table_has_a_row_per_module_at_least() -> None:
    # a guard on the guard: the table was found and read (not an empty match)
    assert len(_documented()) > 100


def test_every_module_states_its_responsibility() -> None:
    bare = sorted(str(p.relative_to(ROOT)) for p in MODULES.values() if _first_line(p) is None)
    assert not bare, f"modules without a docstring's first line (their one responsibility): {bare}"


def test_no_import_cycle_at_module_level() -> None:
    module_level, _, _ = _scan()
    cycles = _cycles(module_level)
    assert not cycles, f"import cycles among module-level imports: {cycles}"


def test_import_cycles_through_functions_only_go_down() -> None:
    module_level, function_level, _ = _scan()
    graph = _union(module_level, function_level)
    cycles = _cycles(graph)
    in_cycles = {m: i for i, group in enumerate(cycles) for m in group}
    edges = sorted(
        (a, b)
        for a, targets in graph.items()
        for b in targets
        if a in in_cycles and in_cycles[a] == in_cycles.get(b)
    )
    listing = "\n".join(f"  {a} -> {b}" for a, b in edges)
    assert len(edges) <= CYCLIC_EDGES_CEILING, (
        f"{len(edges)} imports lie on a cycle (ceiling {CYCLIC_EDGES_CEILING}, issue 30); "
        f"groups: {cycles}\n{listing}"
    )


def test_the_cycle_scan_finds_a_known_ring() -> None:
    # the detector itself: a ring of three and a lone edge
    graph = {"dynsolve.cli": {"dynsolve.api"}, "dynsolve.api": {"dynsolve.files"}}
    graph["dynsolve.files"] = {"dynsolve.cli"}
    graph["dynsolve.units"] = {"dynsolve.format"}
    assert _cycles(graph) == [["dynsolve.api", "dynsolve.cli", "dynsolve.files"]]


def test_no_new_private_name_imported_across_modules() -> None:
    _, _, private = _scan()
    new = sorted(private - PRIVATE_IMPORTS_ALLOWED)
    assert not new, f"private names imported from another module (make them public instead): {new}"


def test_the_private_allow_list_only_shrinks() -> None:
    _, _, private = _scan()
    fixed = sorted(PRIVATE_IMPORTS_ALLOWED - private)
    assert not fixed, f"these are no longer imported: delete them from the allow-list: {fixed}"


def test_files_named_in_the_guides_exist() -> None:
    # CONTRIBUTING.md and the architecture page name files by path (relative to the top
    # folder or to dynsolve/); a renamed or moved module must not leave them pointing at nothing
    named = re.compile(r"(?<![\w/.-])((?:[a-z0-9_-]+/)+[a-z0-9_-]+\.(?:py|md|lark|json))\b")
    gone = sorted(
        f"{guide.name}: {path}"
        for guide in (ROOT / "CONTRIBUTING.md", ARCHITECTURE)
        for path in set(named.findall(guide.read_text()))
        if not (ROOT / path).exists() and not (PACKAGE / path).exists()
    )
    assert not gone, f"files named in the guides that do not exist: {gone}"


# Where Python code is generated and run, or text turned into sympy, as docs/architecture.md's
# Safety section lists them: only ever on sympy objects dynsolve built, never on user text.
# A new place must be reviewed and added to the Safety section, then here.
CODE_FROM_SYMPY = {
    "exec": {"simulate/compiled.py"},
    "compile": {"simulate/compiled.py"},  # the builtin, not re.compile
    "sympify": {"simulate/compiled.py"},
    "lambdify": {
        "grade/vectorized.py",
        "linkage/position.py",
        "modes/oneline_events.py",
        "modes/scene_sketch.py",
        "numbers.py",
        "plots.py",
        "principles/rectilinear.py",
        "principles/vibration.py",
        "rigid3d/onset.py",
        "simulate/chain.py",
        "simulate/compiled.py",
        "simulate/spin3d.py",
        "solver/blocks.py",
    },
    "eval": set(),
    "parse_expr": set(),
}


SYMPY_ENTRIES = ("sympify", "lambdify", "parse_expr")


def _code_calls() -> dict[str, set[str]]:
    """The modules calling each function of :data:`CODE_FROM_SYMPY`."""
    found: dict[str, set[str]] = {name: set() for name in CODE_FROM_SYMPY}
    for path in MODULES.values():
        module = str(path.relative_to(PACKAGE))
        for node in ast.walk(ast.parse(path.read_text(), str(path))):
            if not isinstance(node, ast.Call):
                continue
            func = node.func
            if isinstance(func, ast.Name) and func.id in found:
                found[func.id].add(module)  # exec(…), compile(…), a from-imported sympify(…)
            elif isinstance(func, ast.Attribute) and func.attr in SYMPY_ENTRIES:
                found[func.attr].add(module)  # sympy.lambdify(…), not re.compile(…)
    return found


def test_code_is_generated_only_where_the_safety_section_says() -> None:
    found = _code_calls()
    new = {name: sorted(found[name] - allowed) for name, allowed in CODE_FROM_SYMPY.items()}
    new = {name: modules for name, modules in new.items() if modules}
    assert not new, (
        f"new calls that generate or evaluate code: {new}; they must only see sympy objects "
        "dynsolve built (never user text): review, then list them in docs/architecture.md's "
        "Safety section and in CODE_FROM_SYMPY"
    )
    gone = {name: sorted(allowed - found[name]) for name, allowed in CODE_FROM_SYMPY.items()}
    assert not any(gone.values()), f"no longer called there: drop them from the list: {gone}"


def test_the_safety_section_names_every_such_module() -> None:
    safety = ARCHITECTURE.read_text().partition("## Safety")[2]
    modules = set().union(*CODE_FROM_SYMPY.values())
    missing = sorted(m for m in modules if f"`{m}`" not in safety)
    assert not missing, f"docs/architecture.md's Safety section does not name: {missing}"
