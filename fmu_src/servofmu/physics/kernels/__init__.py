"""The equations, float-or-array: each takes Python floats or numpy arrays (and, compiled,
C doubles), and the exact vectorised path and the per-step path call the same function. This
package imports nothing else from :mod:`servofmu.physics`: everything else is built on it.

- :mod:`.units`: the SI factors and conversions at the edges;
- :mod:`.elementary`: the arithmetic that chooses between math, numpy and C;
- :mod:`.viscosity`: Walther's and Vogel's laws;
- :mod:`.lame`: Lamé's thick cylinders and the mounted raceways (the fits);
- :mod:`.contact`: race geometry, Hertz coefficients, one ball's load and stiffness;
- :mod:`.friction`: the friction terms of a contact and a bearing.

The compiled modules (:mod:`servofmu.physics.compiled`) call them in C through their
``.pxd`` declarations.
"""
