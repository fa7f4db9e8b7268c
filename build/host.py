"""What a non-Python FMI host must set so that a servofmu (pythonfmu) FMU can run.

The FMU's binary does not link libpython: inside a Python process (fmpy, libcosimpy) it uses
the running interpreter. A C/C++ host must preload the interpreter library and put this
environment's site-packages (numpy, scipy) on PYTHONPATH.
"""

from __future__ import annotations

import os
import sys
import sysconfig
from pathlib import Path


def libpython() -> Path | None:
    """The shared Python library of this interpreter, or None if it was built static."""
    libdir = sysconfig.get_config_var("LIBDIR")
    for name in (sysconfig.get_config_var("INSTSONAME"), sysconfig.get_config_var("LDLIBRARY")):
        shared = name and (".so" in name or name.endswith((".dll", ".dylib")))
        if libdir and shared and (Path(libdir) / name).is_file():
            return Path(libdir) / name
    return None


def host_environment() -> dict[str, str]:
    """Environment variables for a non-Python host on this machine (Linux: LD_PRELOAD and
    PYTHONPATH; Windows: PATH and PYTHONPATH)."""
    paths = dict.fromkeys(
        p for p in (sysconfig.get_paths()["purelib"], sysconfig.get_paths()["platlib"]) if p
    )
    env = {"PYTHONPATH": os.pathsep.join(paths)}
    if sys.platform.startswith("win"):
        env["PATH"] = str(Path(sys.base_prefix))
    else:
        lib = libpython()
        if lib is None:
            raise RuntimeError(
                "this Python has no shared libpython (built without --enable-shared): a "
                "non-Python host cannot load a pythonfmu FMU with it"
            )
        env["LD_PRELOAD"] = str(lib)
    return env


def host_environment_text() -> str:
    """Shell ``export`` lines for :func:`host_environment`."""
    if sys.platform.startswith("win"):
        return "\n".join(f"set {k}={v}" for k, v in host_environment().items())
    return "\n".join(f"export {k}={v}" for k, v in host_environment().items())
