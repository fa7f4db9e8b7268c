/* A minimal FMI 2.0 co-simulation host in plain C (no FMI library), used by the tests to run
 * servofmu FMUs outside Python: dlopen the binary, instantiate, set real inputs/parameters,
 * initialise, print the outputs, step, print them again, terminate, free.
 *
 * usage: fmi2_host LIB GUID RESOURCE_URI STEP NSTEPS [s VR VALUE]... [g VR]...
 * prints "init VR VALUE" and "final VR VALUE" lines; exits 1 if any call returns a status
 * worse than fmi2Warning, 2 on usage or loading errors. With FMI2_HOST_EXIT set in the
 * environment it leaves with exit() (exit handlers and library destructors run), else with
 * _exit(). */
#include <dlfcn.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef void *fmi2Component;
typedef void *fmi2ComponentEnvironment;
typedef unsigned int fmi2ValueReference;
typedef double fmi2Real;
typedef int fmi2Boolean;
typedef const char *fmi2String;
typedef enum { fmi2OK, fmi2Warning, fmi2Discard, fmi2Error, fmi2Fatal, fmi2Pending } fmi2Status;
typedef enum { fmi2ModelExchange, fmi2CoSimulation } fmi2Type;
typedef struct {
    void (*logger)(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String, fmi2String, ...);
    void *(*allocateMemory)(size_t, size_t);
    void (*freeMemory)(void *);
    void (*stepFinished)(fmi2ComponentEnvironment, fmi2Status);
    fmi2ComponentEnvironment componentEnvironment;
} fmi2CallbackFunctions;

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status,
                   fmi2String category, fmi2String message, ...) {
    (void)env;
    fprintf(stderr, "[%s] status %d %s: %s\n", name, status, category ? category : "", message);
}

static int failed = 0;
static void check(const char *what, fmi2Status s) {
    if (s > fmi2Warning) {
        fprintf(stderr, "%s returned status %d\n", what, s);
        failed = 1;
    }
}

#define LOAD(type, name)                                                   \
    type name = (type)dlsym(lib, #name);                                   \
    if (!name) { fprintf(stderr, "missing symbol %s\n", #name); return 2; }

typedef fmi2Component (*Instantiate)(fmi2String, fmi2Type, fmi2String, fmi2String,
                                     const fmi2CallbackFunctions *, fmi2Boolean, fmi2Boolean);
typedef fmi2Status (*Setup)(fmi2Component, fmi2Boolean, fmi2Real, fmi2Real, fmi2Boolean, fmi2Real);
typedef fmi2Status (*Simple)(fmi2Component);
typedef fmi2Status (*RealIO)(fmi2Component, const fmi2ValueReference *, size_t, fmi2Real *);
typedef fmi2Status (*RealSet)(fmi2Component, const fmi2ValueReference *, size_t, const fmi2Real *);
typedef fmi2Status (*DoStep)(fmi2Component, fmi2Real, fmi2Real, fmi2Boolean);
typedef void (*Free)(fmi2Component);

int main(int argc, char **argv) {
    if (argc < 6) {
        fprintf(stderr, "usage: %s LIB GUID RESOURCE_URI STEP NSTEPS [s VR VALUE]... [g VR]...\n", argv[0]);
        return 2;
    }
    void *lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!lib) { fprintf(stderr, "dlopen: %s\n", dlerror()); return 2; }
    LOAD(Instantiate, fmi2Instantiate)
    LOAD(Setup, fmi2SetupExperiment)
    LOAD(Simple, fmi2EnterInitializationMode)
    LOAD(Simple, fmi2ExitInitializationMode)
    LOAD(Simple, fmi2Terminate)
    LOAD(RealIO, fmi2GetReal)
    LOAD(RealSet, fmi2SetReal)
    LOAD(DoStep, fmi2DoStep)
    LOAD(Free, fmi2FreeInstance)

    double step = atof(argv[4]);
    int nsteps = atoi(argv[5]);
    fmi2ValueReference set_vr[64], get_vr[64];
    double set_val[64];
    size_t nset = 0, nget = 0;
    for (int i = 6; i < argc; i++) {
        if (!strcmp(argv[i], "s") && i + 2 < argc && nset < 64) {
            set_vr[nset] = (fmi2ValueReference)atoi(argv[i + 1]);
            set_val[nset++] = atof(argv[i + 2]);
            i += 2;
        } else if (!strcmp(argv[i], "g") && i + 1 < argc && nget < 64) {
            get_vr[nget++] = (fmi2ValueReference)atoi(argv[++i]);
        } else {
            fprintf(stderr, "bad argument %s\n", argv[i]);
            return 2;
        }
    }
    fmi2CallbackFunctions cb = {logger, calloc, free, NULL, NULL};
    fmi2Component c = fmi2Instantiate("host", fmi2CoSimulation, argv[2], argv[3], &cb, 0, 0);
    if (!c) { fprintf(stderr, "fmi2Instantiate failed\n"); return 1; }
    double out[64];
    check("fmi2SetupExperiment", fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0));
    check("fmi2EnterInitializationMode", fmi2EnterInitializationMode(c));
    if (nset) check("fmi2SetReal", fmi2SetReal(c, set_vr, nset, set_val));
    check("fmi2ExitInitializationMode", fmi2ExitInitializationMode(c));
    if (nget) check("fmi2GetReal", fmi2GetReal(c, get_vr, nget, out));
    for (size_t k = 0; k < nget; k++) printf("init %u %.17g\n", get_vr[k], out[k]);
    double t = 0.0;
    for (int i = 0; i < nsteps; i++) {
        if (nset) check("fmi2SetReal", fmi2SetReal(c, set_vr, nset, set_val));
        check("fmi2DoStep", fmi2DoStep(c, t, step, 1));
        t += step;
    }
    if (nget) check("fmi2GetReal", fmi2GetReal(c, get_vr, nget, out));
    for (size_t k = 0; k < nget; k++) printf("final %u %.17g\n", get_vr[k], out[k]);
    check("fmi2Terminate", fmi2Terminate(c));
    fmi2FreeInstance(c);
    fflush(stdout);
    fflush(stderr);
    if (getenv("FMI2_HOST_EXIT")) exit(failed);  /* normal exit: runs library destructors */
    /* Leave without running the FMU library's destructors, where pythonfmu finalises the
     * embedded interpreter. Before servofmu.fmus.interpreter_exit put that finalisation
     * first, a normal exit crashed after every FMI call had succeeded; the tests run both. */
    _exit(failed);
}
