"""openemc_launcher: the `linuxcnc` launcher (start a configuration, run its display, clean up)."""
