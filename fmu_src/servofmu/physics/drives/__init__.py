"""The drive train: the actuator of Liu 2014 (:mod:`.actuator`), the DC motor (:mod:`.motor`)
and the servo controller (:mod:`.control`)."""
