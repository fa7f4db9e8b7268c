"""The FMU and SSP build of servofmu (importable as ``servofmu.build``).

:func:`fmu.build_fmu` / :func:`fmu.build_all` run pythonfmu on the slaves of
``servofmu.fmus`` with the servofmu package as a project folder; the slaves write the
complete modelDescription themselves (``ServoSlave.to_xml``). :mod:`.validate` checks built
FMUs, :mod:`.host` tells what a non-Python host must set.
"""
