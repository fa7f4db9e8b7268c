"""The FMU export library, compiled at install time (the project's metadata is in
pyproject.toml; this file only declares the compiled part).

``servofmu.build.export.servofmu_export`` is pythonfmu 0.7.0's FMI 2.0 export library with
servofmu's changes (``build/export/README.md``), compiled into that folder, which is not a
Python package: a shared library, not an importable module. ``servofmu
build`` puts it into every FMU as ``binaries/linux64/<modelIdentifier>.so``. Like pythonfmu's
own binary it is compiled against the stable ABI (``Py_LIMITED_API``) and does not link
libpython: the hosting interpreter provides the Python symbols. The extension is optional:
without a C++17 compiler the install succeeds and the FMUs carry pythonfmu's binary.
"""

import sys
from pathlib import Path

from setuptools import Extension, setup

EXPORT = "build/export/src"


def export_library() -> list[Extension]:
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


setup(ext_modules=export_library())
