
#ifndef PYTHONFMU_SHAREDVALUES_HPP
#define PYTHONFMU_SHAREDVALUES_HPP

// servofmu: the Real values of one slave instance, in a block of memory the Python slave
// allocates and this library reads and writes (servofmu/fmus/shared_values.py describes the
// layout and the rules). fmi2SetReal and fmi2GetReal are served here, without the GIL, when
// the slave's tables allow them; any other call goes to Python as before. The slave is the
// one authority: it writes the tables, and it writes its state and its values back before
// every call into Python returns.

#include "fmi/fmi2TypesPlatform.h"

#include <Python.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace pythonfmu
{

class SharedValues
{
public:
    static constexpr std::int32_t magic = 0x53465631; // "SFV1", shared_values.MAGIC
    // STALE: steps the slave took in compiled code and has not read yet (the slave's own flag)
    enum Header { MAGIC, N_REFERENCES, N_VALUES, PHASE, PENDING, DIRTY, N_PHASES, STALE, HEADER };
    static constexpr std::uint8_t set = 1;
    static constexpr std::uint8_t get = 2;

    SharedValues() = default;
    SharedValues(const SharedValues&) = delete;
    SharedValues& operator=(const SharedValues&) = delete;

    ~SharedValues()
    {
        // the view must be released with the GIL held, by release(): a view still held here
        // (a host that never freed the instance) is left to the process's end
    }

    // Take a view of the slave's block (its attribute "_shared_buffer"), replacing any
    // earlier one. The GIL must be held. A slave without one (pythonfmu's runtime, an older
    // servofmu) or with a block of another layout leaves every call to Python.
    void attach(PyObject* instance)
    {
        release();
        if (instance == nullptr) return;
        PyObject* block = PyObject_GetAttrString(instance, "_shared_buffer");
        if (block == nullptr) {
            PyErr_Clear();
            return;
        }
        if (block != Py_None && PyObject_GetBuffer(block, &view_, PyBUF_WRITABLE) == 0) {
            held_ = true;
            if (!map()) release();
        }
        PyErr_Clear();
        Py_DECREF(block);
    }

    // Give the view back. The GIL must be held.
    void release()
    {
        if (held_) PyBuffer_Release(&view_);
        held_ = false;
        header_ = nullptr;
    }

    // fmi2SetReal: true when served (every reference an input the current state lets a host
    // set, every value finite and within its range), false when Python must answer.
    bool setReal(const fmi2ValueReference vr[], std::size_t nvr, const fmi2Real value[])
    {
        const std::uint8_t* access = table();
        if (access == nullptr) return false;
        for (std::size_t i = 0; i < nvr; ++i) {
            if (vr[i] >= nReferences_ || !(access[vr[i]] & set)) return false;
            const std::int32_t k = index_[vr[i]];
            const double x = value[i];
            if (k < 0 || !std::isfinite(x) || !(x >= lo_[k] && x <= hi_[k])) return false;
        }
        for (std::size_t i = 0; i < nvr; ++i) {
            values_[index_[vr[i]]] = value[i];
        }
        header_[PENDING] = 1;
        header_[DIRTY] = 1;
        return true;
    }

    // fmi2GetReal: true when served (the state allows reading every reference, no
    // computation is due, every value finite), false when Python must answer.
    bool getReal(const fmi2ValueReference vr[], std::size_t nvr, fmi2Real value[]) const
    {
        const std::uint8_t* access = table();
        if (access == nullptr) return false;
        if (header_[DIRTY] != 0 && fresh_[header_[PHASE]] != 0) return false;
        for (std::size_t i = 0; i < nvr; ++i) {
            if (vr[i] >= nReferences_ || !(access[vr[i]] & get)) return false;
            const std::int32_t k = index_[vr[i]];
            if (k < 0 || !std::isfinite(values_[k])) return false;
        }
        for (std::size_t i = 0; i < nvr; ++i) {
            value[i] = values_[index_[vr[i]]];
        }
        return true;
    }

private:
    Py_buffer view_{};
    bool held_ = false;
    std::int32_t* header_ = nullptr;
    double* values_ = nullptr;
    const double* lo_ = nullptr;
    const double* hi_ = nullptr;
    const std::int32_t* index_ = nullptr;
    const std::uint8_t* access_ = nullptr;
    const std::uint8_t* fresh_ = nullptr;
    fmi2ValueReference nReferences_ = 0;
    std::int32_t nPhases_ = 0;

    // The access bits of the current state, or nullptr (no block, or the slave says Python).
    const std::uint8_t* table() const
    {
        if (header_ == nullptr) return nullptr;
        const std::int32_t phase = header_[PHASE];
        if (phase < 0 || phase >= nPhases_) return nullptr;
        return access_ + static_cast<std::size_t>(phase) * nReferences_;
    }

    // Point into the block after checking its header and size.
    bool map()
    {
        auto* bytes = static_cast<unsigned char*>(view_.buf);
        const auto size = static_cast<std::size_t>(view_.len);
        const std::size_t headerSize = HEADER * sizeof(std::int32_t);
        if (bytes == nullptr || size < headerSize || reinterpret_cast<std::uintptr_t>(bytes) % alignof(double) != 0) {
            return false;
        }
        auto* header = reinterpret_cast<std::int32_t*>(bytes);
        const std::int32_t nRefs = header[N_REFERENCES], n = header[N_VALUES], phases = header[N_PHASES];
        if (header[MAGIC] != magic || nRefs < 0 || n < 0 || phases <= 0) return false;
        const std::size_t valuesSize = static_cast<std::size_t>(n) * sizeof(double);
        const std::size_t need = headerSize + 3 * valuesSize + static_cast<std::size_t>(nRefs) * sizeof(std::int32_t) +
            static_cast<std::size_t>(phases) * static_cast<std::size_t>(nRefs) + static_cast<std::size_t>(phases);
        if (size != need) return false;
        values_ = reinterpret_cast<double*>(bytes + headerSize);
        lo_ = values_ + n;
        hi_ = lo_ + n;
        index_ = reinterpret_cast<const std::int32_t*>(hi_ + n);
        access_ = reinterpret_cast<const std::uint8_t*>(index_ + nRefs);
        fresh_ = access_ + static_cast<std::size_t>(phases) * static_cast<std::size_t>(nRefs);
        for (std::int32_t r = 0; r < nRefs; ++r) {
            if (index_[r] >= n) return false;
        }
        nReferences_ = static_cast<fmi2ValueReference>(nRefs);
        nPhases_ = phases;
        header_ = header;
        return true;
    }
};

} // namespace pythonfmu

#endif // PYTHONFMU_SHAREDVALUES_HPP
