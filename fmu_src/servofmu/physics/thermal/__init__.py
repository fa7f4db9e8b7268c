"""Temperature and its effects on the mounting: the parts' temperatures
(:mod:`.temperatures`), the radial thermal coupling of the fits (:mod:`.fits`) and the thermal
network of a mechanism (:mod:`.network`)."""
