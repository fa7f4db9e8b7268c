"""servofmu: temperature-aware physics of servo mechanisms, shipped as FMI 2.0 FMUs.

``servofmu.physics`` holds the pure models (numpy in, numpy out, SI units);
``servofmu.papers`` reproduces the source papers; ``servofmu.cli`` is the command line.
"""

__version__ = "0.1.0"
