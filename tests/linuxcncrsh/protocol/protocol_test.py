"""protocol_test.py: one linuxcncrsh session, request by request (see test.sh)."""
import sys
import time

from rshclient import Session, TIMEOUT_S

s = Session()


def until(req, reply):
    """Repeat req until its reply is reply (a motion has finished), then print it."""
    end = time.time() + TIMEOUT_S
    while time.time() < end:
        got = s.ask(req)
        if got == [reply]:
            print("> %s (until)\n  %s" % (req, reply))
            return
    print("FAIL: %s never replied %s (last %s)" % (req, reply, got))
    sys.exit(1)


print("== before HELLO")
for req in ("get mode", "set estop off", "shutdown", "hello EMC", "hello WRONG me 1.0", "bogus"):
    s.show(req)
s.send("help")
print("> help (first line)")
print("  " + s.ask("")[0])
print("== HELLO, echo, verbose, enable")
for req in ("hello EMC tester 1.0", "get echo", "set echo off", "get echo", "get verbose",
            "set estop off", "set verbose on", "set enable WRONG", "get enable", "set estop off",
            "set enable EMCTOO", "get enable", "get comm_mode", "get comm_prot", "set comm_prot 9.0",
            "get debug", "get wait_mode", "get timeout", "get update"):
    s.show(req)
print("== state and mode")
for req in ("get estop", "set estop off", "get estop", "get machine", "set machine on", "get machine",
            "set set_wait done", "get set_wait", "set wait_mode done", "get mode", "set mode mdi", "get mode", "set mode bogus",
            "set mode manual", "get mode", "get teleop_enable"):
    s.show(req)
print("== coolant, spindle, brake, overrides")
for req in ("get mist", "set mist on", "get mist", "set flood on", "get flood", "set flood maybe",
            "get spindle", "set spindle forward", "get spindle", "set spindle increase", "get spindle",
            "set spindle off", "set spindle reverse 1", "get spindle -1", "set spindle off -1",
            "get spindle 1", "get spindle 5", "get brake", "set brake off", "get brake",
            "set brake on 7", "get feed_override", "set feed_override 75", "get feed_override",
            "get spindle_override", "set spindle_override 120", "get spindle_override"):
    s.show(req)
print("== joints and positions")
for req in ("get joint_homed", "set home 0", "set joint_wait_homed 0", "get joint_homed 0",
            "set home -1", "set joint_wait_homed", "get joint_homed", "get joint_type", "get joint_fault",
            "get joint_limit", "get joint_pos", "get joint_pos 16", "get kinematics_type",
            "get override_limits", "set mode manual", "get teleop_enable"):
    s.show(req)
print("== jogging (teleop after homing)")
s.show("set jog_incr x 60 0.5")
until("get abs_cmd_pos x", "ABS_CMD_POS X 0.500000")
for req in ("get abs_act_pos", "get rel_act_pos", "get pos_offset", "get abs_cmd_pos q",
            "set jog_incr Y -60 0.25"):
    s.show(req)
until("get abs_cmd_pos", "ABS_CMD_POS 0.500000 -0.250000 0.000000 0.000000 0.000000 0.000000")
for req in ("set wait_heartbeat 2", "set jog_stop x", "set jog", "set jog x 60 extra"):
    s.show(req)
print("== MDI and errors")
for req in ("set mode mdi", "set mdi G0 X2 Y0", "get abs_cmd_pos", "set step", "get error", "get error",
            "set mdi M2", "get error", "set override_limits on", "get error", "set teleop_enable on",
            "get operator_text", "get operator_display"):
    s.show(req)
print("== programs")
for req in ("get program", "get program_status", "get program_line", "set mode auto",
            "set open prog.ngc", "get program", "get open", "set run", "get program_status",
            "set wait_mode received", "set abort", "set wait done", "set wait maybe",
            "get program_codes", "get program_units", "get program_linear_units",
            "get program_angular_units"):
    s.show(req.replace("prog.ngc", "prog.ngc"))
print("== units")
for req in ("get user_linear_units", "get user_angular_units", "get display_linear_units",
            "get linear_unit_conversion", "set linear_unit_conversion mm", "get display_linear_units",
            "set angular_unit_conversion rad", "get display_angular_units",
            "set angular_unit_conversion auto", "get angular_unit_conversion", "get ini JOINTS KINS",
            "get ini NOSUCH KINS", "set update none", "set feed_override 50", "get feed_override",
            "set update_status", "get feed_override", "set update auto", "get tool", "get tool_offset"):
    s.show(req)
print("== get plat")
s.send("get plat")
print("  " + s.line())
print("== quit")
s.send("quit")
print("closed after quit:", s.closed())
