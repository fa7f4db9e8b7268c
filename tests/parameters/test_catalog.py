import re

import pytest

from servofmu.parameters import catalog
from servofmu.parameters.catalog import PROVENANCE_KINDS


@pytest.mark.parametrize("table", ["materials", "lubricants", "bearings", "mountings"])
def test_every_record_loads_with_valid_provenance(table):
    loader = {
        "materials": catalog.material,
        "lubricants": catalog.lubricant_record,
        "bearings": catalog.bearing,
        "mountings": catalog.mounting,
    }[table]
    for key in catalog.keys(table):
        rec = loader(key)
        assert rec.provenance or getattr(rec, "lubricant_type", "") == "solid", key
        for field, source in rec.provenance:
            kind = source.split(":")[0]
            assert kind in PROVENANCE_KINDS, (key, field, source)


def test_unknown_keys_are_rejected_with_the_choices():
    with pytest.raises(ValueError, match=re.escape("'6310' is not one of")):
        catalog.bearing("6310")
    with pytest.raises(ValueError, match=re.escape("material key = 'unobtainium'")):
        catalog.material("unobtainium")


def test_materials_are_si(b71803):
    al = catalog.material("cast_aluminium")
    assert al.youngs_modulus == pytest.approx(72e9)
    assert al.expansion == pytest.approx(21.7e-6)
    assert b71803.ring_material.youngs_modulus == pytest.approx(206e9)


def test_printed_reading_swaps_loop_materials_only():
    stated = catalog.mounting("yu2017_gimbal")
    printed = catalog.mounting("yu2017_gimbal_printed")
    mats = {m.name: m.material.key for m in printed.loop.members}
    assert mats == {"frame": "steel_45", "shaft": "cast_aluminium"}
    assert printed.fit == stated.fit  # eq 11-13 keep the aluminium frame bore


def test_dry_film_has_no_viscosity():
    assert catalog.lubricant("mos2_film") is None
