"""The compiled parts of servofmu, built at install time (the project's metadata is in
pyproject.toml; this file only declares the compiled parts). Both are optional: without a
compiler the install succeeds and servofmu runs without them.

``servofmu.physics._pair_kernels`` is ``fmu_src/servofmu/physics/pair_kernels.py`` compiled
by Cython (its pure-Python mode: the same file runs uncompiled), with the SHA-256 of that
source appended as ``SOURCE_HASH``: ``servofmu.physics.continuation`` imports the compiled
module only when it was built from the source next to it. Without a C compiler (or without
Cython) the package runs the Python path. ``pip install -e .`` builds it in place, next to
the source; ``servofmu build`` ships it inside every FMU's copy of the package.

``servofmu.build.export.servofmu_export`` is pythonfmu 0.7.0's FMI 2.0 export library with
servofmu's changes (``build/export/README.md``), compiled into that folder, which is not a
Python package: a shared library, not an importable module. ``servofmu build`` puts it into
every FMU as ``binaries/linux64/<modelIdentifier>.so``. Like pythonfmu's own binary it is
compiled against the stable ABI (``Py_LIMITED_API``) and does not link libpython: the
hosting interpreter provides the Python symbols. Linux only; without a C++17 compiler the
FMUs carry pythonfmu's binary.
"""

import hashlib
import sys
from pathlib import Path

from setuptools import Extension, find_namespace_packages, setup

HERE = Path(__file__).parent
EXPORT = "build/export/src"
#: Where the kernels' source is copied for compilation, with its hash appended (setup.cfg's
#: build_base).
GENERATED = Path(".setuptools-build") / "cython"
#: Cython's directives for the kernels: Python's semantics (division by zero raises), no
#: bounds or wrap-around checks on the tuples the kernels index with constants.
DIRECTIVES = {
    "language_level": 3,
    "boundscheck": False,
    "wraparound": False,
    "initializedcheck": False,
    "cdivision": False,
}


def compiled_kernels() -> list[Extension]:
    """The compiled twin of pair_kernels.py (none when Cython is not installed)."""
    try:
        from Cython.Build import cythonize
    except ImportError:
        return []
    source = HERE / "fmu_src" / "servofmu" / "physics" / "pair_kernels.py"
    text = source.read_bytes()
    digest = hashlib.sha256(text).hexdigest()
    out = HERE / GENERATED / "_pair_kernels.py"
    out.parent.mkdir(parents=True, exist_ok=True)
    generated = text + f'\nSOURCE_HASH = "{digest}"  # appended by setup.py\n'.encode()
    if not out.is_file() or out.read_bytes() != generated:
        out.write_bytes(generated)
    extension = Extension(
        "servofmu.physics._pair_kernels",
        sources=[str(GENERATED / "_pair_kernels.py")],
        extra_compile_args=[] if sys.platform == "win32" else ["-O2", "-g0"],
        optional=True,  # no C compiler: the Python path
    )
    try:
        return cythonize([extension], compiler_directives=DIRECTIVES, quiet=True)
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
            extra_compile_args=["-std=c++17", "-g0"],  # no debug information: 0.4 MB, not 5
            language="c++",
            optional=True,
        )
    ]


setup(packages=packages(), ext_modules=[*compiled_kernels(), *export_library()])
