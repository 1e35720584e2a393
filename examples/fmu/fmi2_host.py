"""A small FMI 2.0 co-simulation host in Python (ctypes, standard library only).

It knows nothing of ModalTyre: it unzips an .fmu, reads modelDescription.xml, loads
binaries/linux64/<modelIdentifier>.so and calls the standard's fmi2 functions. Written from the
FMI 2.0 specification (section 2.1 for the types and callbacks, 4.2 for co-simulation).
"""
import ctypes
import os
import tempfile
import xml.etree.ElementTree as ET
import zipfile

fmi2OK, fmi2Warning, fmi2Discard, fmi2Error, fmi2Fatal, fmi2Pending = range(6)
fmi2ModelExchange, fmi2CoSimulation = 0, 1
STATUS = ["OK", "Warning", "Discard", "Error", "Fatal", "Pending"]

# void logger(env, instanceName, status, category, message, ...): the FMU may pass printf
# arguments; this host prints the message as it comes (this FMU passes none, with '%' as '%%').
LOGGER = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int,
                          ctypes.c_char_p, ctypes.c_char_p)


class CallbackFunctions(ctypes.Structure):
    _fields_ = [("logger", LOGGER), ("allocateMemory", ctypes.c_void_p),
                ("freeMemory", ctypes.c_void_p), ("stepFinished", ctypes.c_void_p),
                ("componentEnvironment", ctypes.c_void_p)]


class FmiError(RuntimeError):
    pass


class Fmu:
    """An unzipped FMU: its description, its library and its variables by name."""

    def __init__(self, fmu_path, folder=None):
        self.folder = folder or tempfile.mkdtemp(prefix="fmu_")
        with zipfile.ZipFile(fmu_path) as z:
            z.extractall(self.folder)
        root = ET.parse(os.path.join(self.folder, "modelDescription.xml")).getroot()
        if root.get("fmiVersion") != "2.0":
            raise FmiError("not an FMI 2.0 FMU")
        cs = root.find("CoSimulation")
        if cs is None:
            raise FmiError("not a co-simulation FMU")
        self.guid = root.get("guid")
        self.identifier = cs.get("modelIdentifier")
        self.variables = {}
        for sv in root.find("ModelVariables"):
            kind = sv[0].tag
            self.variables[sv.get("name")] = (kind, int(sv.get("valueReference")),
                                              sv.get("causality"), sv[0].get("unit"))
        so = os.path.join(self.folder, "binaries", "linux64", self.identifier + ".so")
        self.lib = ctypes.CDLL(so, mode=ctypes.RTLD_LOCAL)
        L = self.lib
        c_vr = ctypes.POINTER(ctypes.c_uint)
        L.fmi2Instantiate.restype = ctypes.c_void_p
        L.fmi2Instantiate.argtypes = [ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p,
                                      ctypes.c_char_p, ctypes.POINTER(CallbackFunctions),
                                      ctypes.c_int, ctypes.c_int]
        L.fmi2FreeInstance.argtypes = [ctypes.c_void_p]
        L.fmi2FreeInstance.restype = None
        L.fmi2SetupExperiment.argtypes = [ctypes.c_void_p, ctypes.c_int, ctypes.c_double,
                                          ctypes.c_double, ctypes.c_int, ctypes.c_double]
        for f in ("fmi2EnterInitializationMode", "fmi2ExitInitializationMode",
                  "fmi2Terminate", "fmi2Reset"):
            getattr(L, f).argtypes = [ctypes.c_void_p]
        L.fmi2GetReal.argtypes = [ctypes.c_void_p, c_vr, ctypes.c_size_t,
                                  ctypes.POINTER(ctypes.c_double)]
        L.fmi2SetReal.argtypes = [ctypes.c_void_p, c_vr, ctypes.c_size_t,
                                  ctypes.POINTER(ctypes.c_double)]
        L.fmi2SetString.argtypes = [ctypes.c_void_p, c_vr, ctypes.c_size_t,
                                    ctypes.POINTER(ctypes.c_char_p)]
        L.fmi2DoStep.argtypes = [ctypes.c_void_p, ctypes.c_double, ctypes.c_double, ctypes.c_int]
        L.fmi2GetVersion.restype = ctypes.c_char_p

    def resource_uri(self):
        return "file://" + os.path.abspath(os.path.join(self.folder, "resources"))


class Instance:
    """One instance of an Fmu, with a logger that keeps and prints its messages."""

    def __init__(self, fmu, name="instance", quiet=False):
        self.fmu, self.name, self.messages = fmu, name, []

        def log(env, inst, status, category, message):
            text = (message or b"").decode().replace("%%", "%")
            self.messages.append((status, text))
            if not quiet:
                print(f"[{name} {STATUS[status]}] {text}")

        self._logger = LOGGER(log)  # kept alive as long as the instance
        self._callbacks = CallbackFunctions(self._logger, None, None, None, None)
        self.c = fmu.lib.fmi2Instantiate(name.encode(), fmi2CoSimulation, fmu.guid.encode(),
                                         fmu.resource_uri().encode(),
                                         ctypes.byref(self._callbacks), 0, 0)
        if not self.c:
            raise FmiError(f"fmi2Instantiate failed: {self.messages}")
        self.time = 0.0

    def _check(self, status, what):
        if status not in (fmi2OK, fmi2Warning):
            raise FmiError(f"{what}: {STATUS[status]} {self.messages[-1:] }")

    def _refs(self, names):
        return (ctypes.c_uint * len(names))(*[self.fmu.variables[n][1] for n in names])

    def set(self, values):
        names = list(values)
        vals = (ctypes.c_double * len(names))(*[values[n] for n in names])
        self._check(self.fmu.lib.fmi2SetReal(self.c, self._refs(names), len(names), vals),
                    "fmi2SetReal")

    def set_string(self, name, value):
        vals = (ctypes.c_char_p * 1)(value.encode())
        self._check(self.fmu.lib.fmi2SetString(self.c, self._refs([name]), 1, vals),
                    "fmi2SetString")

    def get(self, names):
        out = (ctypes.c_double * len(names))()
        self._check(self.fmu.lib.fmi2GetReal(self.c, self._refs(names), len(names), out),
                    "fmi2GetReal")
        return dict(zip(names, out))

    def enter_initialization(self, start=0.0):
        L = self.fmu.lib
        self._check(L.fmi2SetupExperiment(self.c, 0, 0.0, start, 0, 0.0), "fmi2SetupExperiment")
        self._check(L.fmi2EnterInitializationMode(self.c), "fmi2EnterInitializationMode")
        self.time = start

    def exit_initialization(self):
        self._check(self.fmu.lib.fmi2ExitInitializationMode(self.c), "fmi2ExitInitializationMode")

    def initialize(self, start=0.0):
        self.enter_initialization(start)
        self.exit_initialization()

    def step(self, h):
        self._check(self.fmu.lib.fmi2DoStep(self.c, self.time, h, 1), "fmi2DoStep")
        self.time += h

    def free(self):
        if self.c:
            self.fmu.lib.fmi2Terminate(self.c)
            self.fmu.lib.fmi2FreeInstance(self.c)
            self.c = None
