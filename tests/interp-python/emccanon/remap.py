import emccanon


def calls(self, **words):
    """One call of each shape; the canon prints them in rs274's format."""
    line = self.sequence_number
    emccanon.COMMENT("emccanon calls")
    emccanon.SET_FEED_RATE(250)
    emccanon.STRAIGHT_TRAVERSE(line, 1, 2, 3)
    emccanon.STRAIGHT_FEED(line, 4, 5, 6, 0, 0, 0, 0, 0, 0)
    emccanon.ARC_FEED(line, 1, 1, 0.5, 0.5, 1, 6, 0, 0, 0, 0, 0, 0)
    emccanon.DWELL(0.25)
    emccanon.SELECT_PLANE(2)
    emccanon.SET_SPINDLE_SPEED(0, 1200)
    emccanon.START_SPINDLE_CLOCKWISE(0, 1)
    emccanon.MIST_ON()
    emccanon.SET_MOTION_OUTPUT_BIT(3)
    emccanon.SET_AUX_OUTPUT_VALUE(1, 2.5)
    emccanon.USE_TOOL_LENGTH_OFFSET(0, 0, 1.5)
    emccanon.SET_G5X_OFFSET(2, 1, 1, 0)
    emccanon.MESSAGE("position %s, length units %g, queue empty %d" % (
        emccanon.GET_EXTERNAL_POSITION()[:3], emccanon.GET_EXTERNAL_LENGTH_UNITS(),
        emccanon.GET_EXTERNAL_QUEUE_EMPTY()))
    for bad in (lambda: emccanon.STRAIGHT_FEED(line, 1), lambda: emccanon.DWELL("long"),
                lambda: emccanon.SELECT_TOOL()):
        try:
            bad()
        except TypeError as e:
            emccanon.COMMENT("TypeError: %s" % e)
