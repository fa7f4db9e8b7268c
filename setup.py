"""The compiled parts of servofmu, built at install time (the project's metadata is in
pyproject.toml; this file declares the packages and the compiled parts). Both are optional:
without a compiler the install succeeds and servofmu runs without them.

The modules of ``servofmu.physics.compiled.MODULES`` are written in Cython's pure-Python mode
(the same file runs uncompiled): each ``X.py`` with its declarations ``X.pxd`` is compiled by
Cython into the extension ``_X`` beside it, from a copy with the SHA-256 of ``X.py`` and
``X.pxd`` appended as ``SOURCE_HASH``; ``servofmu.physics.compiled`` uses the compiled modules
only when every one was built from the sources next to it. The compiled modules call each
other in C (``cython.cimports`` of the twins' ``.pxd``), so the copies keep the package's
folders. Without a C compiler (or without Cython) the package runs the Python path. ``pip
install -e .`` builds them in place, next to the sources; ``servofmu build`` ships them inside
every FMU's copy of the package.

``servofmu.build.export.servofmu_export`` is pythonfmu 0.7.0's FMI 2.0 export library with
servofmu's changes (``build/export/README.md``), compiled into that folder, which is not a
Python package: a shared library, not an importable module. ``servofmu build`` puts it into
every FMU as ``binaries/linux64/<modelIdentifier>.so``. Like pythonfmu's own binary it is
compiled against the stable ABI (``Py_LIMITED_API``) and does not link libpython: the
hosting interpreter provides the Python symbols. Linux only; without a C++17 compiler the
FMUs carry pythonfmu's binary.
"""

import ast
import hashlib
import sys
from pathlib import Path

from setuptools import Extension, find_namespace_packages, setup

HERE = Path(__file__).parent
EXPORT = "build/export/src"
PHYSICS = Path("fmu_src") / "servofmu" / "physics"
#: Where the compiled modules' sources are copied for compilation, with their hash appended
#: (setup.cfg's build_base), in the package's folders.
GENERATED = Path(".setuptools-build") / "cython"
#: Cython's directives for the compiled modules: Python's semantics (division by zero
#: raises), no bounds or wrap-around checks on the tuples the kernels index with constants.
DIRECTIVES = {
    "language_level": 3,
    "boundscheck": False,
    "wraparound": False,
    "initializedcheck": False,
    "cdivision": False,
}


def compiled_modules() -> tuple[str, ...]:
    """``servofmu.physics.compiled.MODULES``, read from its source (the package is not
    importable while it is being built)."""
    tree = ast.parse((HERE / PHYSICS / "compiled.py").read_text(encoding="utf-8"))
    for node in tree.body:
        if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", "") == "MODULES":
            return ast.literal_eval(node.value)
    raise RuntimeError("servofmu.physics.compiled defines no MODULES")


def _write(path: Path, data: bytes) -> None:
    """Write ``data`` to ``path`` unless it holds them already (Cython rebuilds on a change)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    if not path.is_file() or path.read_bytes() != data:
        path.write_bytes(data)


def _generated(name: str) -> Path:
    """The compilation copy of module ``name`` (``_X.py`` with its hash, ``_X.pxd``) under
    :data:`GENERATED`, with the packages' ``__init__.py`` above it; its path."""
    parent, _, leaf = name.rpartition(".")
    source = HERE / PHYSICS.joinpath(*name.split("."))
    text = source.with_suffix(".py").read_bytes()
    pxd = source.with_suffix(".pxd")
    declarations = pxd.read_bytes() if pxd.is_file() else b""
    digest = hashlib.sha256(text + declarations).hexdigest()
    folder = HERE / GENERATED / "servofmu" / "physics" / Path(*parent.split(".") if parent else ())
    for level in (folder, *folder.parents):
        if level == HERE / GENERATED:
            break
        _write(level / "__init__.py", b"")
    _write(
        folder / f"_{leaf}.py",
        text + f'\nSOURCE_HASH = "{digest}"  # appended by setup.py\n'.encode(),
    )
    if declarations:
        _write(folder / f"_{leaf}.pxd", declarations)
    return (folder / f"_{leaf}.py").relative_to(HERE)


def compiled_kernels() -> list[Extension]:
    """The compiled twins of the modules of :func:`compiled_modules` (none when Cython is not
    installed)."""
    try:
        from Cython.Build import cythonize
    except ImportError:
        return []
    extensions = []
    for name in compiled_modules():
        parent, _, leaf = name.rpartition(".")
        extensions.append(
            Extension(
                ".".join(p for p in ("servofmu.physics", parent, f"_{leaf}") if p),
                sources=[str(_generated(name))],
                # Cython's C for a tuple of C doubles from Python leaves gcc unsure that it is
                # filled on every path (it is: a conversion error raises first)
                extra_compile_args=[]
                if sys.platform == "win32"
                else ["-O2", "-g0", "-Wno-maybe-uninitialized"],
                optional=True,  # no C compiler: the Python path
            )
        )
    try:
        return cythonize(
            extensions,
            compiler_directives=DIRECTIVES,
            include_path=[str(GENERATED)],
            quiet=True,
        )
    except Exception as exc:  # Cython refused the source: the Python path, said aloud
        print(f"warning: servofmu's kernels are not compiled ({exc}); the Python path runs")
        return []


#: The folders that hold the package's parts: {package name: (folder, the subpackages to
#: ship, None: all)}. Every folder below them is a package (a data folder too: setuptools then
#: ships its files, pyproject.toml's package-data, without a warning); caches and build output
#: are not.
PACKAGE_ROOTS = {
    "servofmu": ("fmu_src/servofmu", None),
    "servofmu.build": ("build", ("export", "export.*", "model_descriptions")),
    "servofmu.harness": ("harness", None),
    "servofmu.ssp": ("ssp", None),
    "servofmu.examples": ("examples", None),
}


def packages() -> list[str]:
    """Every package and data folder under :data:`PACKAGE_ROOTS` (their folders mapped by
    pyproject.toml's package-dir)."""
    found = []
    for name, (folder, include) in PACKAGE_ROOTS.items():
        chosen = {"include": include} if include else {}
        subs = find_namespace_packages(folder, exclude=("*__pycache__*", "out", "out.*"), **chosen)
        found += [name, *(f"{name}.{sub}" for sub in subs)]
    return found


def export_library() -> list[Extension]:
    """servofmu's FMI 2.0 export library (none outside Linux)."""
    if not sys.platform.startswith("linux"):  # the FMUs carry pythonfmu's binary elsewhere
        return []
    return [
        Extension(
            "servofmu.build.export.servofmu_export",
            sources=[f"{EXPORT}/pythonfmu/fmi2.cpp", f"{EXPORT}/pythonfmu/PySlaveInstance.cpp"],
            # the headers (and the licence of the sources): in the sdist, and a rebuild on change
            depends=[*sorted(str(p) for p in Path(EXPORT).rglob("*.h*")), "build/export/LICENSE"],
            include_dirs=[EXPORT],
            define_macros=[("Py_LIMITED_API", "0x030B0000")],
            py_limited_api=True,
            # no debug information: 0.4 MB, not 5; pythonfmu's sources compare an int index with
            # a size_t count
            extra_compile_args=["-std=c++17", "-g0", "-Wno-sign-compare"],
            language="c++",
            optional=True,
        )
    ]


setup(packages=packages(), ext_modules=[*compiled_kernels(), *export_library()])
