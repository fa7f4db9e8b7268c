
#ifndef PYTHONFMU_FMU_EXCEPT_HPP
#define PYTHONFMU_FMU_EXCEPT_HPP

#include "fmi/fmi2FunctionTypes.h"

#include <stdexcept>
#include <string>

namespace pythonfmu {

    class fatal_error final : public std::runtime_error {
    public:
        explicit fatal_error(const std::string &msg) : std::runtime_error(msg) {}
    };

    // servofmu: a Python exception that carries an FMI status (an integer attribute
    // ``fmi2_status``: fmi2Discard or fmi2Error). The FMI function logs the message and returns
    // that status; the Python slave instance stays alive and usable.
    class status_error final : public std::runtime_error {
    public:
        status_error(fmi2Status s, const std::string &msg) : std::runtime_error(msg), status(s) {}
        fmi2Status status;
    };

}// namespace pythonfmu

#endif//PYTHONFMU_FMU_EXCEPT_HPP
