"""preview_helpers: the unit and initial G-code a preview needs to start where the machine is."""

AXIS_LETTERS = "XYZABCUVW"
# modal groups of stat.gcodes, in the order their codes are written into the init code
MODAL_ORDER = (3, 6, 14, 7, 5, 4, 9, 12, 10, 16, 8, 11, 13, 15)


def create_unitcode_and_initcode(s, inifile):
    """(unitcode, initcode) for a linuxcnc.stat() s and the configuration's ini object: G20/G21,
    then G53 G0 to the current position (wrapped rotaries modulo 360) and the active modes."""
    wrapped = [inifile.getbool(section, "WRAPPED_ROTARY", fallback=False)
               for section in ("AXIS_A", "AXIS_B", "AXIS_C")]
    s.poll()
    unitcode = "G21" if s.linear_units == 1 else "G20"
    initcode = "G53 G0 "
    for i, letter in enumerate(AXIS_LETTERS):
        if not s.axis_mask & (1 << i):
            continue
        position = s.position[i]
        if 3 <= i <= 5 and wrapped[i - 3]:
            position = position % 360.0
        initcode += "%s%.8f " % (letter, position)
    for group in MODAL_ORDER:
        if s.gcodes[group] > -1:
            initcode += "G" + str(s.gcodes[group] / 10) + " "
    return unitcode, initcode
