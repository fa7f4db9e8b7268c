
#ifndef PYTHONFMU_LOGGER_HPP
#define PYTHONFMU_LOGGER_HPP

#include "fmi/fmi2Functions.h"

#include <algorithm>
#include <string>
#include <vector>

namespace pythonfmu
{

class PyLogger
{

public:
    explicit PyLogger(std::string instanceName)
        : instanceName_(std::move(instanceName))
    { }

    void setDebugLogging(bool flag, const std::vector<std::string>& categories = {})
    {
        debugLogging_ = flag;
        categories_ = categories;
    }

    // Logs a message.
    void log(fmi2Status s, const std::string& message)
    {
        log(s, "", message);
    }

    void log(fmi2Status s, const std::string& category, const std::string& message)
    {
        // servofmu: FMI 2.0 (section 2.1.3) has the logger called for fmi2Warning, fmi2Error and
        // fmi2Fatal and the host show the message; loggingOn and the categories switch the
        // debug messages (fmi2OK, fmi2Discard) only
        if (s == fmi2Warning || s == fmi2Error || s == fmi2Fatal) {
            debugLog(s, category, message);
            return;
        }
        if (debugLogging_) {
            if (categories_.empty() || std::find(categories_.begin(), categories_.end(), category) != categories_.end()) {
                debugLog(s, category, message);
            }
        }
    }

    virtual ~PyLogger() = default;

private:
    bool debugLogging_{false};

protected:
    std::string instanceName_;
    std::vector<std::string> categories_;

    virtual void debugLog(fmi2Status s, const std::string& category, const std::string& message) = 0;
};

} // namespace pythonfmu

#endif // PYTHONFMU_LOGGER_HPP
