"""The example files shipped inside the servofmu package as ``servofmu.examples`` (a user
catalogue, a measured-data file, a plain-fmpy script); ``servofmu examples DIR`` copies them
into a folder of yours."""
