"""The SSP 1.0 system sources (one folder per system: SystemStructure.ssd, one .ssv per
component, variants/), shipped inside the servofmu package as ``servofmu.ssp``;
:mod:`servofmu.build.ssp` packs them with the built FMUs into ``.ssp`` archives."""
