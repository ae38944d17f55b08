from interpreter import INTERP_OK, INTERP_ERROR, INTERP_EXECUTE_FINISH, InterpreterException
import emccanon


def inject(self, **words):
    block = self.blocks[self.remap_level]
    self.params["doubled"] = words["p"] * 2
    self.params[1] = 11
    print("prolog: level %d/%d words %s comment '%s'" % (self.call_level, self.remap_level,
                                                         sorted(words.items()), block.comment))
    return INTERP_OK


def collect(self, **words):
    print("epilog: returned %g (%d), result %g, #1 %g" % (self.return_value, self.value_returned,
                                                          self.params["result"], self.params[1]))
    if self.return_value < 0:
        return "M42x: the procedure reported %g" % self.return_value
    return INTERP_OK


def body(self, **words):
    emccanon.MESSAGE("body: %s at level %d" % (sorted(words.items()), self.remap_level))


def refuse(self, **words):
    self.set_errormsg("M423 refused by its prolog")
    return INTERP_ERROR


def fails_with_code(self, **words):
    return INTERP_ERROR


def raises(self, **words):
    raise RuntimeError("the remap body raised")


def steps(self, **words):
    for x in (1, 2):
        self.execute("G0 X%d" % x)
        yield INTERP_EXECUTE_FINISH
        emccanon.COMMENT("resumed at x=%g" % self.current_x)
    yield INTERP_OK


def cycle_words(self, **words):
    for k, v in words.items():
        self.params[k] = v
    return INTERP_OK


def keep_motion(self, **words):
    self.motion_mode = self.blocks[self.remap_level].executing_remap.motion_code


def nested(self, **words):
    self.execute("M420 P4")
    try:
        self.execute("G1 X1 Y1 F0")
    except InterpreterException as e:
        emccanon.MESSAGE("caught: %s in '%s'" % (e.error_message, e.line_text))
