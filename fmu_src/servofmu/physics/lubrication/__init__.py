"""Lubricants: viscosity laws with the range of their data (:mod:`.viscosity`) and lubricant
records (:mod:`.lubricant`)."""
