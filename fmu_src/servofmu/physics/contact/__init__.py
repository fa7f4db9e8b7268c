"""The ball–race contact: bearing geometry (:mod:`.geometry`), Hertz point contact
(:mod:`.hertz`) and the quasi-static ball loads of one bearing (:mod:`.equilibrium`)."""
