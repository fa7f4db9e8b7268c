"""The compiled parts of servofmu, built at install time (the project's metadata is in
pyproject.toml; this file only declares the compiled parts).

``servofmu.physics._pair_kernels`` is ``fmu_src/servofmu/physics/pair_kernels.py`` compiled
by Cython (its pure-Python mode: the same file runs uncompiled), with the SHA-256 of that
source appended as ``SOURCE_HASH``: ``servofmu.physics.continuation`` imports the compiled
module only when it was built from the source next to it. The extension is optional: without
a C compiler (or without Cython) the install succeeds and the package runs the Python path.
``pip install -e .`` builds it in place, next to the source.
"""

import hashlib
import sys
from pathlib import Path

from setuptools import Extension, setup

HERE = Path(__file__).parent
#: Where the source is copied for compilation, with its hash appended (setup.cfg's build_base).
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


setup(ext_modules=[*compiled_kernels()])
