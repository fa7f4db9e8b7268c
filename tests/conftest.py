import pytest
from hypothesis import settings

from servofmu.parameters import catalog
from servofmu.physics.bearing import BearingPair

# Property tests run derandomized (a fixed sequence of examples: a CI run is reproducible and
# finds the same cases on every machine); `pytest --hypothesis-profile=fuzz` draws new random
# examples and keeps the failures it finds in .hypothesis/ for local fuzzing. A counterexample
# found either way becomes an @example of its test.
settings.register_profile("ci", derandomize=True, database=None, print_blob=True)
settings.register_profile("fuzz", derandomize=False, print_blob=True)
settings.load_profile("ci")


@pytest.fixture(scope="session")
def b71803():
    return catalog.bearing("71803")


@pytest.fixture(scope="session")
def yu_pair():
    """Yu's stated data read literally: the frame a rigid E·A/L tube (overloaded at −40 °C,
    unloaded when warm)."""
    return BearingPair.from_catalog("yu2017_gimbal_rigid", "krytox_143aa")


@pytest.fixture(scope="session")
def ning_pair():
    return BearingPair.from_catalog("ning_space_shaft", "mos2_film")


@pytest.fixture(scope="session")
def fmus(tmp_path_factory):
    """The five FMUs, built once per test session."""
    from servofmu.build.fmu import FMUS, build_all

    out = tmp_path_factory.mktemp("fmus")
    return {p.stem: p for p in build_all(out, FMUS)}


@pytest.fixture(scope="session")
def stock_fmus(tmp_path_factory):
    """The five FMUs with pythonfmu's binary, as an install without a C++ compiler builds
    them."""
    from servofmu.build import exportlib, fmu

    out = tmp_path_factory.mktemp("stock_fmus")
    found = exportlib.compiled_export
    exportlib.compiled_export = fmu.compiled_export = lambda: None
    try:
        return {p.stem: p for p in fmu.build_all(out, fmu.FMUS, systems=False)}
    finally:
        exportlib.compiled_export = fmu.compiled_export = found


def pytest_addoption(parser):
    parser.addoption(
        "--long",
        action="store_true",
        help="full sizes of the robustness tests (10,000 fuzz cases per FMU, 1,000,000-step "
        "soaks): `make test-long`",
    )


@pytest.fixture(scope="session")
def long_mode(request) -> bool:
    return bool(request.config.getoption("--long"))
