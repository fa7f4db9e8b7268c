
#include "fmu_except.hpp"

#include "pythonfmu/Logger.hpp"
#include "pythonfmu/PyState.hpp"
#include "pythonfmu/SharedValues.hpp"
#include "pythonfmu/SlaveInstance.hpp"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <regex>
#include <sstream>
#include <string>
#include <utility>

using namespace pythonfmu;

namespace
{
std::string getline(const std::filesystem::path& fileName)
{
    std::string line;
    std::ifstream infile(fileName);
    std::getline(infile, line);
    return line;
}

PyObject* findClass(const std::string& resources, const std::string& moduleName)
{
    // Initialize the Python interpreter
    std::string filename = resources + "/" + moduleName + ".py";
    std::string deepestFile;
    int deepestChain = 0;

    // Read and execute the Python file
    std::ifstream file;
    file.open(filename);

    if (!file.is_open()) {
        return nullptr;
    }

    std::stringstream fileContents;
    std::string line;

    while (std::getline(file, line)) {
        fileContents << line << "\n";
    }

    // Compile python code so classes are added to the namespace
    PyObject* pyModule = PyImport_ImportModule(moduleName.c_str());

    if (pyModule == nullptr) {
        return nullptr;
    }
    PyObject* pGlobals = PyModule_GetDict(pyModule);
    PyObject* pLocals = PyDict_New();
    PyObject* pCode = Py_CompileString(fileContents.str().c_str(), moduleName.c_str(), Py_file_input);

    if (pCode != nullptr) {
        PyObject* pResult = PyEval_EvalCode(pCode, pGlobals, pLocals);
        Py_XDECREF(pResult);
    } else {
        // servofmu: the compilation error stays set for the caller to report; the host's
        // interpreter is not finalised and the borrowed module dict not released
        Py_DECREF(pyModule);
        Py_DECREF(pLocals);
        file.close();
        return nullptr;
    }

    fileContents.clear();
    PyObject *key, *value;
    Py_ssize_t pos = 0;

    while (PyDict_Next(pLocals, &pos, &key, &value)) {
        // Check if element in namespace is a class
        if (!PyType_Check(value)) {
            continue;
        }

        PyObject* pMroAttribute = PyObject_GetAttrString(value, "__mro__");

        if (pMroAttribute != nullptr && PySequence_Check(pMroAttribute)) {
            std::regex pattern("<class '[^']+\\.([^']+)'");
            PyObject* pMROList = PySequence_List(pMroAttribute);

            for (Py_ssize_t i = 0; i < PyList_Size(pMROList); ++i) {
                PyObject* pItem = PyList_GetItem(pMROList, i);
                std::smatch match;
                const char* className = PyBytes_AsString(PyUnicode_AsUTF8String(PyObject_Repr(pItem)));

                std::string str(className);
                const bool isMatch = std::regex_search(str, match, pattern);

                // If regex match is successfull, and found Fmi2Slave at the deepest level then update state
                if (isMatch && i > deepestChain && match[1] == "Fmi2Slave") {
                    deepestFile = PyBytes_AsString(PyUnicode_AsUTF8String(key));
                    deepestChain = i;
                }
            }
        }
        Py_DECREF(pMroAttribute);
    }

    PyObject* pyClassName = Py_BuildValue("s", deepestFile.c_str());
    PyObject* pyClass = PyObject_GetAttr(pyModule, pyClassName);

    // Clean up Python objects
    Py_DECREF(pCode);
    Py_DECREF(pLocals);
    Py_DECREF(pyModule); // servofmu: pGlobals is borrowed (PyModule_GetDict): not released
    file.close();
    Py_DECREF(pyClassName);
    return pyClass;
}

void py_safe_run(const std::function<void(PyGILState_STATE gilState)>& f)
{
    PyGILState_STATE gil_state = PyGILState_Ensure();
    f(gil_state);
    PyGILState_Release(gil_state);
}

} // namespace

class PySlaveInstance : public SlaveInstance
{
public:
    explicit PySlaveInstance(fmu_data data)
        : data_(std::move(data))
    {
        py_safe_run([this](PyGILState_STATE gilState) {
            // Append resources path to python sys path
            PyObject* sys_module = PyImport_ImportModule("sys");
            if (sys_module == nullptr) {
                handle_py_exception("[ctor] PyImport_ImportModule", gilState);
            }
            PyObject* sys_path = PyObject_GetAttrString(sys_module, "path");
            Py_DECREF(sys_module);
            if (sys_path == nullptr) {
                handle_py_exception("[ctor] PyObject_GetAttrString", gilState);
            }
            int success = PyList_Insert(sys_path, 0, PyUnicode_FromString(resourceLocation().c_str()));

            Py_DECREF(sys_path);
            if (success != 0) {
                handle_py_exception("[ctor] PyList_Insert", gilState);
            }

            std::string moduleName = getline(resourceLocation() + "/slavemodule.txt");

            pClass_ = findClass(resourceLocation(), moduleName);
            if (pClass_ == nullptr) {
                handle_py_exception("[ctor] findClass", gilState);
            }

            initialize(gilState);
        });
    }

    void clearLogBuffer() const
    {
        clearLogStrBuffer();
        // servofmu: nothing queued (most calls): no Python objects made to find that out
        if (pMessages_ == nullptr || !PyList_Check(pMessages_) || PyList_Size(pMessages_) == 0) {
            return;
        }

        PyObject* msgField = Py_BuildValue("s", "msg");
        PyObject* categoryField = Py_BuildValue("s", "category");
        PyObject* statusField = Py_BuildValue("s", "status");

        if (pMessages_ != nullptr && PyList_Check(pMessages_)) {
            const auto size = PyList_Size(pMessages_);
            for (auto i = 0; i < size; i++) {
                PyObject* msg = PyList_GetItem(pMessages_, i);

                const auto msgAttr = PyObject_GetAttr(msg, msgField);
                const auto categoryAttr = PyObject_GetAttr(msg, categoryField);
                const auto statusAttr = PyObject_GetAttr(msg, statusField);

                // servofmu: a message that is not text, or a category that is not, is skipped
                // or dropped instead of dereferencing NULL; no reference is leaked
                PyObject* msgValue = (msgAttr != nullptr && PyUnicode_Check(msgAttr))
                    ? PyUnicode_AsEncodedString(msgAttr, "utf-8", "backslashreplace")
                    : nullptr;
                PyObject* categoryValue = (categoryAttr != nullptr && PyUnicode_Check(categoryAttr))
                    ? PyUnicode_AsEncodedString(categoryAttr, "utf-8", "backslashreplace")
                    : nullptr;
                const auto statusValue = statusAttr != nullptr
                    ? static_cast<fmi2Status>(PyLong_AsLong(statusAttr))
                    : fmi2Error;
                PyErr_Clear();
                Py_XDECREF(msgAttr);
                Py_XDECREF(categoryAttr);
                Py_XDECREF(statusAttr);
                if (msgValue == nullptr) {
                    Py_XDECREF(categoryValue);
                    continue;
                }
                logStrBuffer.emplace_back(msgValue);
                const char* categoryStr = "";
                if (categoryValue != nullptr) {
                    logStrBuffer.emplace_back(categoryValue);
                    categoryStr = PyBytes_AsString(categoryValue);
                }

                log(statusValue, categoryStr, PyBytes_AsString(msgValue));
            }
            PyList_SetSlice(pMessages_, 0, size, nullptr);
        }

        Py_DECREF(msgField);
        Py_DECREF(categoryField);
        Py_DECREF(statusField);
    }

    void initialize(PyGILState_STATE gilState)
    {
        if (pClass_ == nullptr) { // servofmu: lost with a fatal error; no call through NULL
            PyGILState_Release(gilState);
            throw fatal_error("the slave class was released after a fatal error: free this instance");
        }
        shared_.release(); // servofmu: the old instance's values
        Py_XDECREF(pInstance_);
        pInstance_ = nullptr;
        Py_XDECREF(pMessages_);
        pMessages_ = nullptr;

        PyObject* args = PyTuple_New(0);
        PyObject* kwargs = Py_BuildValue("{ss,ss,sn,si}",
            "instance_name", data_.instanceName.c_str(),
            "resources", data_.resourceLocation.c_str(),
            "logger", data_.fmiLogger,
            "visible", data_.visible);
        pInstance_ = PyObject_Call(pClass_, args, kwargs);
        Py_DECREF(args);
        Py_DECREF(kwargs);
        if (pInstance_ == nullptr) {
            handle_py_exception("[initialize] PyObject_Call", gilState);
        }
        pMessages_ = PyObject_CallMethod(pInstance_, "_get_log_queue", nullptr);
        shared_.attach(pInstance_); // servofmu: the values it shares, if any
        if (pDoStep_ == nullptr) pDoStep_ = PyUnicode_InternFromString("do_step");
        PyErr_Clear();
    }

    void SetupExperiment(double startTime, std::optional<double> stop, std::optional<double> tolerance) override
    {
        py_safe_run([this, startTime, stop, tolerance](PyGILState_STATE gilState) {
            PyObject* pyStop = stop ? Py_BuildValue("d", *stop) : (Py_INCREF(Py_None), Py_None);
            PyObject* pyTol = tolerance ? Py_BuildValue("d", *tolerance) : (Py_INCREF(Py_None), Py_None);

            auto f = PyObject_CallMethod(pInstance_, "setup_experiment", "(dOO)", startTime, pyStop, pyTol);

            Py_DECREF(pyStop);
            Py_DECREF(pyTol);

            if (f == nullptr) {
                handle_py_exception("[setupExperiment] PyObject_CallMethod", gilState);
            }
            Py_DECREF(f);
            clearLogBuffer();
        });
    }

    void EnterInitializationMode() override
    {
        py_safe_run([this](PyGILState_STATE gilState) {
            auto f = PyObject_CallMethod(pInstance_, "enter_initialization_mode", nullptr);
            if (f == nullptr) {
                handle_py_exception("[enterInitializationMode] PyObject_CallMethod", gilState);
            }
            Py_DECREF(f);
            clearLogBuffer();
        });
    }

    void ExitInitializationMode() override
    {
        py_safe_run([this](PyGILState_STATE gilState) {
            auto f = PyObject_CallMethod(pInstance_, "exit_initialization_mode", nullptr);
            if (f == nullptr) {
                handle_py_exception("[exitInitializationMode] PyObject_CallMethod", gilState);
            }
            Py_DECREF(f);
            clearLogBuffer();
        });
    }

    bool Step(double currentTime, double stepSize) override
    {
        bool status;
        py_safe_run([this, &status, currentTime, stepSize](PyGILState_STATE gilState) {
            // servofmu: the method's name made once per instance, the arguments as objects
            // (no format string parsed, no name decoded on every step)
            PyObject* t = PyFloat_FromDouble(currentTime);
            PyObject* h = PyFloat_FromDouble(stepSize);
            auto f = (pDoStep_ != nullptr && t != nullptr && h != nullptr)
                ? PyObject_CallMethodObjArgs(pInstance_, pDoStep_, t, h, nullptr)
                : PyObject_CallMethod(pInstance_, "do_step", "(dd)", currentTime, stepSize);
            Py_XDECREF(t);
            Py_XDECREF(h);
            if (f == nullptr) {
                handle_py_exception("[doStep] PyObject_CallMethod", gilState);
            }
            status = static_cast<bool>(PyObject_IsTrue(f));
            Py_DECREF(f);
            clearLogBuffer();
        });

        return status;
    }

    void Reset() override
    {
        py_safe_run([this](PyGILState_STATE gilState) {
            initialize(gilState);
        });
    }

    void Terminate() override
    {
        py_safe_run([this](PyGILState_STATE gilState) {
            auto f = PyObject_CallMethod(pInstance_, "terminate", nullptr);
            if (f == nullptr) {
                handle_py_exception("[terminate] PyObject_CallMethod", gilState);
            }
            Py_DECREF(f);
            clearLogBuffer();
        });
    }

    void SetReal(const fmi2ValueReference* vr, std::size_t nvr, const fmi2Real* values) override
    {
        requireArrays("fmi2SetReal", vr, values, nvr);
        if (shared_.setReal(vr, nvr, values)) return; // servofmu: served without Python
        py_safe_run([this, &vr, nvr, &values](PyGILState_STATE gilState) {
            PyObject* vrs = PyList_New(nvr);
            PyObject* refs = PyList_New(nvr);
            for (int i = 0; i < nvr; i++) {
                PyList_SetItem(vrs, i, Py_BuildValue("i", vr[i]));
                PyList_SetItem(refs, i, Py_BuildValue("d", values[i]));
            }

            auto f = PyObject_CallMethod(pInstance_, "set_real", "(OO)", vrs, refs);
            Py_DECREF(vrs);
            Py_DECREF(refs);
            if (f == nullptr) {
                handle_py_exception("[setReal] PyObject_CallMethod", gilState);
            }
            Py_DECREF(f);
            clearLogBuffer();
        });
    }

    void SetInteger(const fmi2ValueReference* vr, std::size_t nvr, const fmi2Integer* values) override
    {
        requireArrays("fmi2SetInteger", vr, values, nvr);
        py_safe_run([this, &vr, nvr, &values](PyGILState_STATE gilState) {
            PyObject* vrs = PyList_New(nvr);
            PyObject* refs = PyList_New(nvr);
            for (int i = 0; i < nvr; i++) {
                PyList_SetItem(vrs, i, Py_BuildValue("i", vr[i]));
                PyList_SetItem(refs, i, Py_BuildValue("i", values[i]));
            }

            auto f = PyObject_CallMethod(pInstance_, "set_integer", "(OO)", vrs, refs);
            Py_DECREF(vrs);
            Py_DECREF(refs);
            if (f == nullptr) {
                handle_py_exception("[setInteger] PyObject_CallMethod", gilState);
            }
            Py_DECREF(f);
            clearLogBuffer();
        });
    }

    void SetBoolean(const fmi2ValueReference* vr, std::size_t nvr, const fmi2Boolean* values) override
    {
        requireArrays("fmi2SetBoolean", vr, values, nvr);
        py_safe_run([this, &vr, nvr, &values](PyGILState_STATE gilState) {
            PyObject* vrs = PyList_New(nvr);
            PyObject* refs = PyList_New(nvr);
            for (int i = 0; i < nvr; i++) {
                PyList_SetItem(vrs, i, Py_BuildValue("i", vr[i]));
                PyList_SetItem(refs, i, PyBool_FromLong(values[i]));
            }

            auto f = PyObject_CallMethod(pInstance_, "set_boolean", "(OO)", vrs, refs);
            Py_DECREF(vrs);
            Py_DECREF(refs);
            if (f == nullptr) {
                handle_py_exception("[setBoolean] PyObject_CallMethod", gilState);
            }
            Py_DECREF(f);
            clearLogBuffer();
        });
    }

    void SetString(const fmi2ValueReference* vr, std::size_t nvr, fmi2String const* values) override
    {
        requireArrays("fmi2SetString", vr, values, nvr);
        py_safe_run([this, &vr, nvr, &values](PyGILState_STATE gilState) {
            PyObject* vrs = PyList_New(nvr);
            PyObject* refs = PyList_New(nvr);
            for (int i = 0; i < nvr; i++) {
                PyList_SetItem(vrs, i, Py_BuildValue("i", vr[i]));
                // servofmu: NULL as None, bytes that are not UTF-8 replaced (never a NULL item)
                PyObject* text = values[i] == nullptr
                    ? (Py_INCREF(Py_None), Py_None)
                    : PyUnicode_DecodeUTF8(values[i], static_cast<Py_ssize_t>(std::strlen(values[i])), "replace");
                PyList_SetItem(refs, i, text);
            }

            auto f = PyObject_CallMethod(pInstance_, "set_string", "(OO)", vrs, refs);
            Py_DECREF(vrs);
            Py_DECREF(refs);
            if (f == nullptr) {
                handle_py_exception("[setString] PyObject_CallMethod", gilState);
            }
            Py_DECREF(f);
            clearLogBuffer();
        });
    }

    void GetReal(const fmi2ValueReference* vr, std::size_t nvr, fmi2Real* values) const override
    {
        requireArrays("fmi2GetReal", vr, values, nvr);
        if (shared_.getReal(vr, nvr, values)) return; // servofmu: served without Python
        py_safe_run([this, &vr, nvr, &values](PyGILState_STATE gilState) {
            PyObject* vrs = PyList_New(nvr);
            for (int i = 0; i < nvr; i++) {
                PyList_SetItem(vrs, i, Py_BuildValue("i", vr[i]));
            }

            auto refs = PyObject_CallMethod(pInstance_, "get_real", "O", vrs);
            Py_DECREF(vrs);
            if (refs == nullptr) {
                handle_py_exception("[getReal] PyObject_CallMethod", gilState);
            }
            requireList(refs, nvr, "get_real", gilState);

            for (int i = 0; i < nvr; i++) {
                PyObject* value = PyList_GetItem(refs, i);
                values[i] = PyFloat_AsDouble(value);
            }
            Py_DECREF(refs);
            clearLogBuffer();
        });
    }

    void GetInteger(const fmi2ValueReference* vr, std::size_t nvr, fmi2Integer* values) const override
    {
        requireArrays("fmi2GetInteger", vr, values, nvr);
        py_safe_run([this, &vr, nvr, &values](PyGILState_STATE gilState) {
            PyObject* vrs = PyList_New(nvr);
            for (int i = 0; i < nvr; i++) {
                PyList_SetItem(vrs, i, Py_BuildValue("i", vr[i]));
            }
            auto refs = PyObject_CallMethod(pInstance_, "get_integer", "O", vrs);
            Py_DECREF(vrs);
            if (refs == nullptr) {
                handle_py_exception("[getInteger] PyObject_CallMethod", gilState);
            }
            requireList(refs, nvr, "get_integer", gilState);

            for (int i = 0; i < nvr; i++) {
                PyObject* value = PyList_GetItem(refs, i);
                values[i] = static_cast<fmi2Integer>(PyLong_AsLong(value));
            }
            Py_DECREF(refs);
            clearLogBuffer();
        });
    }

    void GetBoolean(const fmi2ValueReference* vr, std::size_t nvr, fmi2Boolean* values) const override
    {
        requireArrays("fmi2GetBoolean", vr, values, nvr);
        py_safe_run([this, &vr, nvr, &values](PyGILState_STATE gilState) {
            PyObject* vrs = PyList_New(nvr);
            for (int i = 0; i < nvr; i++) {
                PyList_SetItem(vrs, i, Py_BuildValue("i", vr[i]));
            }
            auto refs = PyObject_CallMethod(pInstance_, "get_boolean", "O", vrs);
            Py_DECREF(vrs);
            if (refs == nullptr) {
                handle_py_exception("[getBoolean] PyObject_CallMethod", gilState);
            }
            requireList(refs, nvr, "get_boolean", gilState);

            for (int i = 0; i < nvr; i++) {
                PyObject* value = PyList_GetItem(refs, i);
                values[i] = PyObject_IsTrue(value);
            }
            Py_DECREF(refs);
            clearLogBuffer();
        });
    }

    void GetString(const fmi2ValueReference* vr, std::size_t nvr, fmi2String* values) const override
    {
        requireArrays("fmi2GetString", vr, values, nvr);
        py_safe_run([this, &vr, nvr, &values](PyGILState_STATE gilState) {
            clearStrBuffer();
            PyObject* vrs = PyList_New(nvr);
            for (int i = 0; i < nvr; i++) {
                PyList_SetItem(vrs, i, Py_BuildValue("i", vr[i]));
            }
            auto refs = PyObject_CallMethod(pInstance_, "get_string", "O", vrs);
            Py_DECREF(vrs);
            if (refs == nullptr) {
                handle_py_exception("[getString] PyObject_CallMethod", gilState);
            }
            requireList(refs, nvr, "get_string", gilState);

            for (int i = 0; i < nvr; i++) {
                PyObject* item = PyList_GetItem(refs, i);
                PyObject* value = PyUnicode_Check(item)
                    ? PyUnicode_AsEncodedString(item, "utf-8", "backslashreplace")
                    : nullptr;
                if (value == nullptr) { // servofmu: not text: an error, not a NULL dereference
                    PyErr_Clear();
                    Py_DECREF(refs);
                    fail("get_string returned a value that is not text", gilState);
                }
                values[i] = PyBytes_AsString(value);
                strBuffer.emplace_back(value);
            }
            Py_DECREF(refs);
            clearLogBuffer();
        });
    }

    void GetFMUstate(fmi2FMUstate& state) override
    {
        py_safe_run([this, &state](PyGILState_STATE gilState) {
            auto f = PyObject_CallMethod(pInstance_, "_get_fmu_state", nullptr);
            if (f == nullptr) {
                handle_py_exception("[_get_fmu_state] PyObject_CallMethod", gilState);
            }
            state = reinterpret_cast<fmi2FMUstate*>(f);
            clearLogBuffer();
        });
    }

    void SetFMUstate(const fmi2FMUstate& state) override
    {
        requireState("fmi2SetFMUstate", state);
        py_safe_run([this, &state](PyGILState_STATE gilState) {
            auto pyState = reinterpret_cast<PyObject*>(state);
            auto f = PyObject_CallMethod(pInstance_, "_set_fmu_state", "(O)", pyState);
            if (f == nullptr) {
                handle_py_exception("[_set_fmu_state] PyObject_CallMethod", gilState);
            }
            Py_DECREF(f);
            clearLogBuffer();
        });
    }

    void FreeFMUstate(fmi2FMUstate& state) override
    {
        py_safe_run([this, &state](PyGILState_STATE gilState) {
            auto f = reinterpret_cast<PyObject*>(state);
            Py_XDECREF(f);
            state = nullptr; // servofmu: FMI 2.0 sets the host's pointer to NULL
        });
    }

    size_t SerializedFMUstateSize(const fmi2FMUstate& state) override
    {
        size_t size;
        requireState("fmi2SerializedFMUstateSize", state);
        py_safe_run([this, &state, &size](PyGILState_STATE gilState) {
            auto pyState = reinterpret_cast<PyObject*>(state);
            PyObject* pyStateBytes = PyObject_CallMethod(pClass_, "_fmu_state_to_bytes", "(O)", pyState);
            if (pyStateBytes == nullptr) {
                handle_py_exception("[SerializedFMUstateSize] PyObject_CallMethod", gilState);
            }
            size = PyBytes_Size(pyStateBytes);
            Py_DECREF(pyStateBytes);
            clearLogBuffer();
        });
        return size;
    }

    void SerializeFMUstate(const fmi2FMUstate& state, fmi2Byte* bytes, size_t size) override
    {
        requireState("fmi2SerializeFMUstate", state);
        if (size > 0 && bytes == nullptr) {
            throw std::invalid_argument("fmi2SerializeFMUstate: serializedState is NULL");
        }
        py_safe_run([this, &state, &bytes, size](PyGILState_STATE gilState) {
            auto pyState = reinterpret_cast<PyObject*>(state);
            PyObject* pyStateBytes = PyObject_CallMethod(pClass_, "_fmu_state_to_bytes", "(O)", pyState);
            if (pyStateBytes == nullptr) {
                handle_py_exception("[SerializeFMUstate] PyObject_CallMethod", gilState);
            }
            char* c = PyBytes_AsString(pyStateBytes);
            if (c == nullptr) {
                handle_py_exception("[SerializeFMUstate] PyBytes_AsString", gilState);
            }
            const auto actual = static_cast<size_t>(PyBytes_Size(pyStateBytes));
            if (size != actual) { // servofmu: never read or write past either buffer
                Py_DECREF(pyStateBytes);
                fail("fmi2SerializeFMUstate: size = " + std::to_string(size) + " is not the "
                     "state's size " + std::to_string(actual) + " (fmi2SerializedFMUstateSize)", gilState);
            }
            for (size_t i = 0; i < size; i++) {
                bytes[i] = c[i];
            }
            Py_DECREF(pyStateBytes);
            clearLogBuffer();
        });
    }

    void DeSerializeFMUstate(const fmi2Byte bytes[], size_t size, fmi2FMUstate& state) override
    {
        if (size > 0 && bytes == nullptr) {
            throw std::invalid_argument("fmi2DeSerializeFMUstate: serializedState is NULL");
        }
        py_safe_run([this, &bytes, size, &state](PyGILState_STATE gilState) {
            PyObject* pyStateBytes = PyBytes_FromStringAndSize(bytes, static_cast<Py_ssize_t>(size));
            if (pyStateBytes == nullptr) { // servofmu: e.g. no memory for a wrong size: an error
                PyErr_Clear();
                fail("fmi2DeSerializeFMUstate: size = " + std::to_string(size) + " cannot be copied", gilState);
            }
            PyObject* pyState = PyObject_CallMethod(pClass_, "_fmu_state_from_bytes", "(O)", pyStateBytes);
            if (pyState == nullptr) {
                handle_py_exception("[DeSerializeFMUstate] PyObject_CallMethod", gilState);
            }
            state = reinterpret_cast<fmi2FMUstate*>(pyState);
            Py_DECREF(pyStateBytes);
            clearLogBuffer();
        });
    }

    ~PySlaveInstance() override
    {
        py_safe_run([this](PyGILState_STATE) {
            cleanPyObject();
        });
    }

private:
    fmu_data data_;

    mutable PyObject* pClass_{};
    mutable PyObject* pInstance_{};
    mutable PyObject* pMessages_{};

    mutable std::vector<PyObject*> strBuffer;
    mutable std::vector<PyObject*> logStrBuffer;
    mutable SharedValues shared_; // servofmu: the instance's Real values shared with the slave
    mutable PyObject* pDoStep_{}; // servofmu: the name "do_step"

    std::string resourceLocation() const
    {
        return data_.resourceLocation;
    }

    void log(fmi2Status s, const std::string& message) const
    {
        data_.fmiLogger->log(s, message);
    }

    void log(fmi2Status s, const std::string& category, const std::string& message) const
    {
        data_.fmiLogger->log(s, category, message);
    }

    void clearStrBuffer() const
    {
        if (!strBuffer.empty()) {
            for (auto obj : strBuffer) {
                Py_DECREF(obj);
            }
            strBuffer.clear();
        }
    }

    void clearLogStrBuffer() const
    {
        if (!logStrBuffer.empty()) {
            for (auto obj : logStrBuffer) {
                Py_DECREF(obj);
            }
            logStrBuffer.clear();
        }
    }

    void cleanPyObject() const
    {
        clearLogBuffer();
        clearLogStrBuffer();
        clearStrBuffer();
        shared_.release(); // servofmu: before the instance that owns the values
        // servofmu: forgotten once released: a later call or the destructor never releases
        // them again (that double release crashed hosts after a fatal error)
        Py_XDECREF(pClass_);
        pClass_ = nullptr;
        Py_XDECREF(pInstance_);
        pInstance_ = nullptr;
        Py_XDECREF(pMessages_);
        pMessages_ = nullptr;
        Py_XDECREF(pDoStep_);
        pDoStep_ = nullptr;
    }

    // servofmu: an error status for a host's mistake, raised with the GIL released
    [[noreturn]] static void fail(const std::string& message, PyGILState_STATE gilState)
    {
        PyGILState_Release(gilState);
        throw std::runtime_error(message);
    }

    template<typename T, typename V>
    static void requireArrays(const char* function, const T* vr, const V* values, std::size_t nvr)
    {
        if (nvr > 0 && (vr == nullptr || values == nullptr)) {
            throw std::invalid_argument(std::string(function) + ": vr[] or value[] is NULL with nvr = " + std::to_string(nvr));
        }
    }

    static void requireState(const char* function, const fmi2FMUstate& state)
    {
        if (state == nullptr) {
            throw std::invalid_argument(std::string(function) + ": the FMU state is NULL");
        }
    }

    // the Python getter answered a list of nvr values (else an error, nothing read)
    static void requireList(PyObject* refs, std::size_t nvr, const char* method, PyGILState_STATE gilState)
    {
        if (!PyList_Check(refs) || static_cast<std::size_t>(PyList_Size(refs)) != nvr) {
            Py_DECREF(refs);
            fail(std::string(method) + " did not return one value per value reference", gilState);
        }
    }

    // The FMI status a Python exception asks for (attribute fmi2_status: fmi2Discard or
    // fmi2Error), or -1 for any other exception.
    static int reportedStatus(PyObject* exception)
    {
        if (exception == nullptr) return -1;
        PyObject* attr = PyObject_GetAttrString(exception, "fmi2_status");
        if (attr == nullptr) {
            PyErr_Clear();
            return -1;
        }
        const long value = PyLong_Check(attr) ? PyLong_AsLong(attr) : -1;
        Py_DECREF(attr);
        PyErr_Clear();
        return (value == fmi2Discard || value == fmi2Error) ? static_cast<int>(value) : -1;
    }

    static std::string text(PyObject* object)
    {
        std::string out = "unknown error";
        PyObject* str = object != nullptr ? PyObject_Str(object) : nullptr;
        PyObject* bytes = str != nullptr ? PyUnicode_AsEncodedString(str, "utf-8", "backslashreplace") : nullptr;
        if (bytes != nullptr) out = PyBytes_AsString(bytes);
        Py_XDECREF(bytes);
        Py_XDECREF(str);
        PyErr_Clear();
        return out;
    }


    void handle_py_exception(const std::string& what, PyGILState_STATE gilState) const
    {
        const auto err = PyErr_Occurred();
        if (err != nullptr) {
            PyObject *pExcType, *pExcValue, *pExcTraceback;
            PyErr_Fetch(&pExcType, &pExcValue, &pExcTraceback);
            PyErr_NormalizeException(&pExcType, &pExcValue, &pExcTraceback);

            // servofmu: an exception carrying an FMI status is the slave's answer to a host's
            // mistake: that status, its message logged, the instance kept
            const int status = reportedStatus(pExcValue);
            if (status >= 0) {
                const std::string message = text(pExcValue);
                Py_XDECREF(pExcType);
                Py_XDECREF(pExcValue);
                Py_XDECREF(pExcTraceback);
                clearLogBuffer();
                PyGILState_Release(gilState);
                throw status_error(static_cast<fmi2Status>(status), message);
            }

            cleanPyObject();

            std::ostringstream oss;
            oss << "Fatal py exception encountered: ";
            oss << what << "\n";
            if (pExcValue != nullptr) {
                PyObject* pRepr = PyObject_Repr(pExcValue);
                PyObject* pyStr = PyUnicode_AsEncodedString(pRepr, "utf-8", "backslashreplace");
                oss << PyBytes_AsString(pyStr);
                Py_DECREF(pyStr);
                Py_DECREF(pRepr);
            } else {
                oss << "unknown error";
            }

            PyErr_Clear();

            Py_XDECREF(pExcType);
            Py_XDECREF(pExcValue);
            Py_XDECREF(pExcTraceback);

            PyGILState_Release(gilState);

            throw fatal_error(oss.str());
        }
    }
};

namespace
{

std::mutex pyStateMutex{};
std::shared_ptr<PyState> pyState{};

} // namespace

std::unique_ptr<SlaveInstance> pythonfmu::createInstance(fmu_data data)
{
    {
        auto const ensurePyStateAlive = [&]() {
            auto const lock = std::lock_guard{pyStateMutex};
            if (nullptr == pyState) pyState = std::make_shared<PyState>();
        };

        ensurePyStateAlive();
        auto c = std::make_unique<PySlaveInstance>(data);
        data.pyState = pyState;
        return c;
    }
}


extern "C" {

// The PyState instance owns it's own thread for constructing and destroying the Py* from the same thread.
// Creation of an std::thread increments ref counter of a shared library. So, when the client unloads the library
// the library won't be freed, as std::thread is alive, and the std::thread itself waits for de-initialization request.
// Thus, use DllMain on Windows and __attribute__((destructor)) on Linux for signaling to the PyState about de-initialization.
void finalizePythonInterpreter()
{
    pyState = nullptr;
}
}

namespace
{

#ifdef _WIN32
#    include <windows.h>

BOOL APIENTRY DllMain(HMODULE hModule,
    DWORD ul_reason_for_call,
    LPVOID lpReserved)
{
    switch (ul_reason_for_call) {
        case DLL_PROCESS_ATTACH:
            break;
        case DLL_THREAD_ATTACH:
        case DLL_THREAD_DETACH:
            break;
        case DLL_PROCESS_DETACH:
            finalizePythonInterpreter();
            break;
    }
    return TRUE;
}
#elif defined(__linux__)
__attribute__((destructor)) void onLibraryUnload()
{
    finalizePythonInterpreter();
}
#else
#    error port the code
#endif
} // namespace
