"""Helpers to drive the built FMUs through fmpy's low-level FMU2Slave in the tests."""

from __future__ import annotations

from fmpy import extract, read_model_description
from fmpy.fmi1 import FMICallException, calloc, free
from fmpy.fmi2 import (
    FMU2Slave,
    fmi2CallbackAllocateMemoryTYPE,
    fmi2CallbackFreeMemoryTYPE,
    fmi2CallbackFunctions,
    fmi2CallbackLoggerTYPE,
)

from servofmu.build.archive import read_member
from servofmu.build.choices import choice_items
from servofmu.build.xmlsafe import parse

_KEEP = []  # ctypes callbacks and extracted folders must outlive the instances


class Fmu:
    """One FMU instance with name-based access and a captured log."""

    def __init__(self, path, instance_name="inst", unzip_dir=None, log=None, md=None):
        self.md = md or read_model_description(str(path))
        self.dir = unzip_dir or extract(str(path))
        self.vr = {v.name: v.valueReference for v in self.md.modelVariables}
        self.type = {v.name: v.type for v in self.md.modelVariables}
        md_xml = read_member(path, "modelDescription.xml")
        self.items = choice_items(parse(md_xml, "modelDescription.xml"))  # choice → {name: value}
        self.log: list[tuple[int, str]] = [] if log is None else log

        def logger(env, name, status, category, message):
            text = message.decode(errors="replace") if isinstance(message, bytes) else message
            self.log.append((status, str(text)))

        cb = fmi2CallbackFunctions()
        cb.logger = fmi2CallbackLoggerTYPE(logger)
        cb.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        cb.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        _KEEP.append((cb, logger, self.dir))
        self.slave = FMU2Slave(
            guid=self.md.guid,
            unzipDirectory=self.dir,
            modelIdentifier=self.md.coSimulation.modelIdentifier,
            instanceName=instance_name,
        )
        self.slave.instantiate(callbacks=cb, loggingOn=True)

    def set(self, **values):
        """Set variables by name; a choice takes an item name or its value."""
        for name, value in values.items():
            kind = self.type[name]
            if name in self.items and isinstance(value, str):
                value = self.items[name][value]
            if kind == "Real":
                self.slave.setReal([self.vr[name]], [float(value)])
            elif kind == "String":
                self.slave.setString([self.vr[name]], [str(value)])
            elif kind == "Boolean":
                self.slave.setBoolean([self.vr[name]], [bool(value)])
            else:
                self.slave.setInteger([self.vr[name]], [int(value)])

    def get(self, *names):
        out = []
        for n in names:
            if self.type[n] == "Boolean":
                out.append(bool(self.slave.getBoolean([self.vr[n]])[0]))
            else:
                out.append(self.slave.getReal([self.vr[n]])[0])
        return out if len(out) > 1 else out[0]

    def init(self, start=0.0, **values):
        self.slave.setupExperiment(startTime=start)
        self.slave.enterInitializationMode()
        self.set(**values)
        self.slave.exitInitializationMode()
        return self

    def outputs(self):
        return [v.name for v in self.md.modelVariables if v.causality == "output"]

    def real_outputs(self):
        names = [n for n in self.outputs() if self.type[n] == "Real"]
        return self.slave.getReal([self.vr[n] for n in names])

    def close(self):
        """fmi2Terminate where it is legal (FMI 2.0: after a step or a failed one; the error
        state has none), then fmi2FreeInstance."""
        try:
            self.slave.terminate()
        except FMICallException:
            pass
        finally:
            self.slave.freeInstance()
