
#include "Logger.hpp"
#include "SlaveInstance.hpp"
#include "fmi/fmi2Functions.h"
#include "fmu_except.hpp"

#include <cctype>
#include <exception>
#include <fstream>
#include <limits>
#include <sstream>
#include <memory>
#include <optional>
#include <regex>

namespace
{

class Fmi2Logger : public pythonfmu::PyLogger
{

public:
    explicit Fmi2Logger(const std::string& instanceName, const fmi2CallbackFunctions* f)
        : PyLogger(instanceName)
        , f_(f)
    { }

protected:
    void debugLog(fmi2Status s, const std::string& category, const std::string& message) override
    {
        f_->logger(f_->componentEnvironment, instanceName_.c_str(),
            s, category.empty() ? nullptr : category.c_str(), message.c_str());
    }

private:
    const fmi2CallbackFunctions* f_;
};

// servofmu: the folder of a file URI ("file:///a%20b", "file:/a%20b", "file://localhost/a") or
// of a plain path; percent escapes decoded
std::string resourcePath(const std::string& uri)
{
    std::string path = uri;
    if (path.rfind("file://localhost/", 0) == 0) {
        path = path.substr(16);
    } else if (path.rfind("file:///", 0) == 0) {
        path = path.substr(7);
    } else if (path.rfind("file:/", 0) == 0) {
        path = path.substr(5);
    }
#ifdef _MSC_VER
    if (path.size() > 2 && path[0] == '/' && path[2] == ':') path = path.substr(1);
#endif
    std::string out;
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (path[i] == '%' && i + 2 < path.size() && std::isxdigit(static_cast<unsigned char>(path[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(path[i + 2]))) {
            out += static_cast<char>(std::stoi(path.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += path[i];
        }
    }
    while (out.size() > 1 && out.back() == '/') out.pop_back();
    return out;
}

// servofmu: the guid attribute of <resources>/../modelDescription.xml, or "" when unreadable
std::string modelGuid(const std::string& resources)
{
    std::ifstream file(resources + "/../modelDescription.xml");
    if (!file.is_open()) return "";
    std::stringstream text;
    text << file.rdbuf();
    std::smatch match;
    const auto xml = text.str();
    if (std::regex_search(xml, match, std::regex("\\sguid\\s*=\\s*\"([^\"]*)\""))) {
        return match[1];
    }
    return "";
}

// A struct that holds all the data for one model instance.
struct Fmi2Component
{

    Fmi2Component(std::unique_ptr<pythonfmu::SlaveInstance> slave, std::unique_ptr<Fmi2Logger> logger)
        : lastSuccessfulTime{std::numeric_limits<double>::quiet_NaN()}
        , slave(std::move(slave))
        , logger(std::move(logger))
    { }

    // servofmu: the slave goes first: its destructor logs the messages still queued, through
    // the logger (members are destroyed in reverse order, which freed the logger first)
    ~Fmi2Component()
    {
        slave.reset();
    }

    double lastSuccessfulTime{0};
    bool wantsToTerminate{false};

    std::unique_ptr<pythonfmu::SlaveInstance> slave;
    std::unique_ptr<Fmi2Logger> logger;
};

} // namespace


// FMI functions
extern "C" {

// =============================================================================
// FMI 2.0 functions
// =============================================================================

// servofmu: identifies this export and its protocol to the Python slave: a Python exception
// with an attribute fmi2_status (fmi2Discard or fmi2Error) is answered with that status and
// its message, and the instance stays alive; fmi2Warning, fmi2Error and fmi2Fatal messages
// reach the host's logger whatever loggingOn says; from version 2, fmi2SetReal and
// fmi2GetReal are served from the values a slave shares (SharedValues.hpp).
const char* servofmuExport()
{
    return "servofmu-export 2 (pythonfmu 0.7.0, patched)";
}


const char* fmi2GetTypesPlatform()
{
    return fmi2TypesPlatform;
}


const char* fmi2GetVersion()
{
    return "2.0";
}


fmi2Component fmi2Instantiate(fmi2String instanceName,
    fmi2Type fmuType,
    fmi2String fmuGUID,
    fmi2String fmuResourceLocation,
    const fmi2CallbackFunctions* functions,
    fmi2Boolean visible,
    fmi2Boolean loggingOn)
{
    // servofmu: every argument checked before it is used; a refusal is logged (when there is a
    // logger) and answered with NULL
    if (functions == nullptr || functions->logger == nullptr) {
        return nullptr;
    }
    auto logger = std::make_unique<Fmi2Logger>(instanceName != nullptr ? instanceName : "", functions);
    logger->setDebugLogging(loggingOn);
    const auto refuse = [&logger](const std::string& message) -> fmi2Component {
        logger->log(fmi2Error, "fmi2Instantiate: " + message);
        return nullptr;
    };
    if (instanceName == nullptr || std::string(instanceName).empty()) {
        return refuse("instanceName is NULL or empty");
    }
    if (fmuType != fmi2CoSimulation) {
        return refuse("fmuType = " + std::to_string(static_cast<int>(fmuType)) + ": this FMU supports co-simulation (fmi2CoSimulation = 1) only");
    }
    if (fmuResourceLocation == nullptr) {
        return refuse("fmuResourceLocation is NULL");
    }

    std::string resources;
    try {
        resources = resourcePath(fmuResourceLocation);
    } catch (const std::exception& e) {
        return refuse(e.what());
    }
    const auto expected = modelGuid(resources);
    if (!expected.empty() && (fmuGUID == nullptr || expected != fmuGUID)) {
        return refuse(std::string("fmuGUID = ") + (fmuGUID != nullptr ? fmuGUID : "NULL") +
                      " is not this FMU's guid " + expected + " (modelDescription.xml)");
    }

    try {

        auto instance = pythonfmu::createInstance(
            {logger.get(),
                visible == fmi2True,
                instanceName,
                resources,
                nullptr});

        auto component = std::make_unique<Fmi2Component>(std::move(instance), std::move(logger));
        return component.release();
    } catch (const std::exception& e) {
        logger->log(fmi2Fatal, e.what());
        return nullptr;
    }
}


void fmi2FreeInstance(fmi2Component c)
{
    if (c) {
        const auto component = static_cast<Fmi2Component*>(c);
        delete component;
    }
}


fmi2Status fmi2SetDebugLogging(
    fmi2Component c,
    fmi2Boolean loggingOn,
    size_t nCategories,
    const fmi2String categories[])
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;

    std::vector<std::string> categoriesVec;
    if (nCategories > 0) {
        if (categories == nullptr) { // servofmu: no read through NULL
            component->logger->log(fmi2Error, "fmi2SetDebugLogging: categories is NULL with nCategories = " + std::to_string(nCategories));
            return fmi2Error;
        }
        // Convert categories to std::vector<std::string>
        categoriesVec.reserve(nCategories);
        for (size_t i = 0; i < nCategories; ++i) {
            if (categories[i] != nullptr) categoriesVec.emplace_back(categories[i]);
        }
    }

    component->logger->setDebugLogging(loggingOn, categoriesVec);

    return fmi2OK;
}


fmi2Status fmi2SetupExperiment(
    fmi2Component c,
    fmi2Boolean toleranceDefined,
    fmi2Real tolerance,
    fmi2Real startTime,
    fmi2Boolean stopTimeDefined,
    fmi2Real stopTime)
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    try {
        component->slave->SetupExperiment(
            startTime,
            stopTimeDefined ? std::optional(stopTime) : std::nullopt,
            toleranceDefined ? std::optional(tolerance) : std::nullopt);
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}


fmi2Status fmi2EnterInitializationMode(fmi2Component c)
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    try {
        component->slave->EnterInitializationMode();
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}


fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    try {
        component->slave->ExitInitializationMode();
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}


fmi2Status fmi2Terminate(fmi2Component c)
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    try {
        component->slave->Terminate();
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}


fmi2Status fmi2Reset(fmi2Component c)
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    try {
        component->slave->Reset();
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}


fmi2Status fmi2GetReal(
    fmi2Component c,
    const fmi2ValueReference vr[],
    size_t nvr,
    fmi2Real value[])
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    try {
        component->slave->GetReal(vr, nvr, value);
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}

fmi2Status fmi2GetInteger(
    fmi2Component c,
    const fmi2ValueReference vr[],
    size_t nvr,
    fmi2Integer value[])
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    try {
        component->slave->GetInteger(vr, nvr, value);
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}

fmi2Status fmi2GetBoolean(
    fmi2Component c,
    const fmi2ValueReference vr[],
    size_t nvr,
    fmi2Boolean value[])
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    try {
        component->slave->GetBoolean(vr, nvr, value);
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}

fmi2Status fmi2GetString(
    fmi2Component c,
    const fmi2ValueReference vr[],
    size_t nvr,
    fmi2String value[])
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    try {
        component->slave->GetString(vr, nvr, value);
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}


fmi2Status fmi2SetReal(
    fmi2Component c,
    const fmi2ValueReference vr[],
    size_t nvr,
    const fmi2Real value[])
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    try {
        component->slave->SetReal(vr, nvr, value);
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}

fmi2Status fmi2SetInteger(
    fmi2Component c,
    const fmi2ValueReference vr[],
    size_t nvr,
    const fmi2Integer value[])
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    try {
        component->slave->SetInteger(vr, nvr, value);
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}

fmi2Status fmi2SetBoolean(
    fmi2Component c,
    const fmi2ValueReference vr[],
    size_t nvr,
    const fmi2Boolean value[])
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    try {
        component->slave->SetBoolean(vr, nvr, value);
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}

fmi2Status fmi2SetString(
    fmi2Component c,
    const fmi2ValueReference vr[],
    size_t nvr,
    const fmi2String value[])
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    try {
        component->slave->SetString(vr, nvr, value);
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}


fmi2Status fmi2GetFMUstate(
    fmi2Component c,
    fmi2FMUstate* state)
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    if (state == nullptr) { // servofmu: no write through NULL
        component->logger->log(fmi2Error, "fmi2GetFMUstate: FMUstate is NULL");
        return fmi2Error;
    }
    try {
        component->slave->GetFMUstate(*state);
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}

fmi2Status fmi2SetFMUstate(
    fmi2Component c,
    fmi2FMUstate state)
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    try {
        component->slave->SetFMUstate(state);
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}

fmi2Status fmi2FreeFMUstate(
    fmi2Component c,
    fmi2FMUstate* state)
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    if (state == nullptr) { // servofmu: no write through NULL
        component->logger->log(fmi2Error, "fmi2FreeFMUstate: FMUstate is NULL");
        return fmi2Error;
    }
    try {
        component->slave->FreeFMUstate(*state);
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}

fmi2Status fmi2SerializedFMUstateSize(
    fmi2Component c,
    fmi2FMUstate state,
    size_t* size)
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    if (size == nullptr) { // servofmu: no write through NULL
        component->logger->log(fmi2Error, "fmi2SerializedFMUstateSize: size is NULL");
        return fmi2Error;
    }
    try {
        *size = component->slave->SerializedFMUstateSize(state);
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}

fmi2Status fmi2SerializeFMUstate(
    fmi2Component c,
    fmi2FMUstate state,
    fmi2Byte bytes[],
    size_t size)
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    try {
        component->slave->SerializeFMUstate(state, bytes, size);
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}

fmi2Status fmi2DeSerializeFMUstate(
    fmi2Component c,
    const fmi2Byte bytes[],
    size_t size,
    fmi2FMUstate* state)
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    if (state == nullptr) { // servofmu: no write through NULL
        component->logger->log(fmi2Error, "fmi2DeSerializeFMUstate: FMUstate is NULL");
        return fmi2Error;
    }
    try {
        component->slave->DeSerializeFMUstate(bytes, size, *state);
        return fmi2OK;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}


fmi2Status fmi2GetDirectionalDerivative(
    fmi2Component c,
    const fmi2ValueReference[],
    size_t,
    const fmi2ValueReference[],
    size_t,
    const fmi2Real[],
    fmi2Real[])
{
    if (c == nullptr) return fmi2Error;
    static_cast<Fmi2Component*>(c)->logger->log(
        fmi2Error,
        "cppfmu",
        "FMI function not supported: fmi2GetDirectionalDerivative");
    return fmi2Error;
}

fmi2Status fmi2SetRealInputDerivatives(
    fmi2Component c,
    const fmi2ValueReference[],
    size_t,
    const fmi2Integer[],
    const fmi2Real[])
{
    if (c == nullptr) return fmi2Error;
    static_cast<Fmi2Component*>(c)->logger->log(
        fmi2Error,
        "cppfmu",
        "FMI function not supported: fmi2SetRealInputDerivatives");
    return fmi2Error;
}

fmi2Status fmi2GetRealOutputDerivatives(
    fmi2Component c,
    const fmi2ValueReference[],
    size_t,
    const fmi2Integer[],
    fmi2Real[])
{
    if (c == nullptr) return fmi2Error;
    static_cast<Fmi2Component*>(c)->logger->log(
        fmi2Error,
        "cppfmu",
        "FMI function not supported: fmiGetRealOutputDerivatives");
    return fmi2Error;
}

fmi2Status fmi2DoStep(
    fmi2Component c,
    fmi2Real currentCommunicationPoint,
    fmi2Real communicationStepSize,
    fmi2Boolean /*noSetFMUStatePriorToCurrentPoint*/)
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    try {
        double endTime = currentCommunicationPoint;
        const auto ok = component->slave->DoStep(
            currentCommunicationPoint,
            communicationStepSize);
        if (ok) {
            component->lastSuccessfulTime =
                currentCommunicationPoint + communicationStepSize;
            return fmi2OK;
        }

        component->lastSuccessfulTime = endTime;
        component->wantsToTerminate = true;
        return fmi2Discard;
    } catch (const pythonfmu::fatal_error& e) {
        component->logger->log(fmi2Fatal, e.what());
        return fmi2Fatal;
    } catch (const pythonfmu::status_error& e) {
        component->logger->log(e.status, e.what());
        return e.status;
    } catch (const std::exception& e) {
        component->logger->log(fmi2Error, e.what());
        return fmi2Error;
    }
}

fmi2Status fmi2CancelStep(fmi2Component c)
{
    if (c == nullptr) return fmi2Error;
    static_cast<Fmi2Component*>(c)->logger->log(
        fmi2Error,
        "FMI function not supported: fmi2CancelStep");
    return fmi2Error;
}


/* Inquire slave status */
fmi2Status fmi2GetStatus(
    fmi2Component c,
    const fmi2StatusKind,
    fmi2Status*)
{
    if (c == nullptr) return fmi2Error;
    static_cast<Fmi2Component*>(c)->logger->log(
        fmi2Error,
        "FMI function not supported: fmi2GetStatus");
    return fmi2Error;
}

fmi2Status fmi2GetRealStatus(
    fmi2Component c,
    const fmi2StatusKind s,
    fmi2Real* value)
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    if (value == nullptr) { // servofmu: no write through NULL
        component->logger->log(fmi2Error, "fmi2GetRealStatus: value is NULL");
        return fmi2Error;
    }
    if (s == fmi2LastSuccessfulTime) {
        *value = component->lastSuccessfulTime;
        return fmi2OK;
    } else {
        component->logger->log(
            fmi2Discard,
            "Invalid status inquiry for fmi2GetRealStatus");
        return fmi2Discard;
    }
}

fmi2Status fmi2GetIntegerStatus(
    fmi2Component c,
    const fmi2StatusKind,
    fmi2Integer*)
{
    if (c == nullptr) return fmi2Error;
    static_cast<Fmi2Component*>(c)->logger->log(
        fmi2Discard,
        "FMI function not supported: fmi2GetIntegerStatus");
    return fmi2Discard;
}

fmi2Status fmi2GetBooleanStatus(
    fmi2Component c,
    const fmi2StatusKind s,
    fmi2Boolean* value)
{
    const auto component = static_cast<Fmi2Component*>(c);
    if (component == nullptr) return fmi2Error;
    if (value == nullptr) { // servofmu: no write through NULL
        component->logger->log(fmi2Error, "fmi2GetBooleanStatus: value is NULL");
        return fmi2Error;
    }
    if (s == fmi2Terminated) {
        *value = component->wantsToTerminate ? fmi2True : fmi2False;
        return fmi2OK;
    }
    component->logger->log(
        fmi2Discard, "FMI function not supported: fmi2GetBooleanStatus");
    return fmi2Discard;
}

fmi2Status fmi2GetStringStatus(
    fmi2Component c,
    const fmi2StatusKind,
    fmi2String*)
{
    if (c == nullptr) return fmi2Error;
    static_cast<Fmi2Component*>(c)->logger->log(
        fmi2Discard, "FMI function not supported: fmi2GetStringStatus");
    return fmi2Discard;
}
}
