"""Tool-change glue written for this test: T selects, M6 loads, S sets the speed, M61 declares a tool."""
from interpreter import INTERP_OK, INTERP_EXECUTE_FINISH
import emccanon


def t_prolog(self, **words):
    block = self.blocks[self.remap_level]
    if not block.t_flag:
        return "T needs a tool number"
    status, pocket = self.find_tool_pocket(block.t_number)
    if status != INTERP_OK:
        return "T%d: no such tool in the table" % block.t_number
    self.params["tool"] = block.t_number
    self.params["pocket"] = pocket
    return INTERP_OK


def t_epilog(self, **words):
    if self.return_value <= 0:
        return "T aborted by its procedure (%g)" % self.return_value
    self.selected_tool = int(self.params["tool"])
    self.selected_pocket = int(self.params["pocket"])
    emccanon.SELECT_TOOL(self.selected_tool)
    return INTERP_OK


def m6_prolog(self, **words):
    if self.selected_pocket < 0:
        return "M6: no tool prepared"
    self.params["tool_in_spindle"] = self.current_tool
    self.params["selected_tool"] = self.selected_tool
    return INTERP_OK


def m6_epilog(self, **words):
    if self.return_value <= 0:
        return "M6 aborted by its procedure"
    emccanon.CHANGE_TOOL(self.selected_pocket)
    self.current_pocket = self.selected_pocket
    self.set_tool_parameters()
    self.selected_pocket = -1
    self.toolchange_flag = True
    yield INTERP_EXECUTE_FINISH


def s_prolog(self, **words):
    block = self.blocks[self.remap_level]
    self.params["speed"] = block.s_number
    return INTERP_OK


def s_epilog(self, **words):
    speed = self.params["speed"]
    emccanon.SET_SPINDLE_SPEED(0, speed)
    self.speed[0] = speed
    return INTERP_OK


def m61_body(self, **words):
    block = self.blocks[self.remap_level]
    status, pocket = self.find_tool_pocket(block.q_number)
    if status != INTERP_OK:
        return "M61: tool %d is not in the table" % block.q_number
    emccanon.CHANGE_TOOL_NUMBER(pocket)
    self.current_pocket = pocket
    self.set_tool_parameters()
