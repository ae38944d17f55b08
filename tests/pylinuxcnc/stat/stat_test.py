"""stat_test.py: types and startup values of linuxcnc.stat (python.md sec. 1, nml.md sec. 5)."""
import linuxcnc

TYPES = {
    int: "echo_serial_number state task_mode task_state exec_state interp_state call_level "
         "read_line motion_line current_line program_units interpreter_errcode task_paused "
         "queued_mdi_commands joints spindles axis_mask motion_mode queue active_queue "
         "motion_id id probe_val kinematics_type motion_type num_extrajoints pocket_prepped "
         "tool_in_spindle tool_from_pocket mist flood estop debug g5x_index heartbeat taskbeat",
    bool: "optional_stop block_delete input_timeout enabled inpos queue_full paused "
          "single_stepping probe_tripped probing feed_override_enabled adaptive_feed_enabled "
          "feed_hold_enabled",
    float: "rotation_xy delay_left linear_units angular_units cycle_time feedrate rapidrate "
           "velocity acceleration max_velocity max_acceleration distance_to_go current_vel",
    str: "file command ini_filename",
}
TUPLES = {"position": (9, float), "actual_position": (9, float), "probed_position": (9, float),
          "dtg": (9, float), "g5x_offset": (9, float), "g92_offset": (9, float),
          "tool_offset": (9, float), "joint_position": (16, float),
          "joint_actual_position": (16, float), "homed": (16, int), "limit": (16, int),
          "din": (64, int), "dout": (64, int), "ain": (64, float), "aout": (64, float),
          "misc_error": (64, int), "gcodes": (17, int), "mcodes": (10, int),
          "settings": (5, float), "joint": (16, dict), "axis": (9, dict), "spindle": (8, dict)}

s = linuxcnc.stat()
print("before poll:", s.task_state, s.echo_serial_number, s.linear_units)
s.poll()
bad = []
for kind, names in TYPES.items():
    for name in names.split():
        if type(getattr(s, name)) is not kind:
            bad.append("%s is %s" % (name, type(getattr(s, name)).__name__))
for name, (length, kind) in TUPLES.items():
    value = getattr(s, name)
    if type(value) is not tuple or len(value) != length or any(type(v) is not kind for v in value):
        bad.append("%s is not a %d-tuple of %s" % (name, length, kind.__name__))
print("attribute types:", bad or "all as documented")
print("joint keys:", sorted(s.joint[0]))
print("axis keys:", sorted(s.axis[0]))
print("spindle keys:", sorted(s.spindle[0]))

print("task_state ESTOP:", s.task_state == linuxcnc.STATE_ESTOP)
print("task_mode MANUAL:", s.task_mode == linuxcnc.MODE_MANUAL)
print("motion_mode FREE:", s.motion_mode == linuxcnc.TRAJ_MODE_FREE)
print("interp/exec/state:", s.interp_state, s.exec_state, s.state)
print("estop, enabled, inpos:", s.estop, s.enabled, s.inpos)
print("homed:", s.homed[:s.joints])
print("overrides:", s.feedrate, s.rapidrate)
print("flags:", s.optional_stop, s.block_delete, s.feed_override_enabled,
      s.adaptive_feed_enabled, s.feed_hold_enabled)
print("program_units:", s.program_units, "g5x_index:", s.g5x_index,
      "pocket_prepped:", s.pocket_prepped, "tool_in_spindle:", s.tool_in_spindle)
print("gcodes:", s.gcodes)
print("mcodes:", s.mcodes)
print("units:", round(s.linear_units, 6), s.angular_units, "joints:", s.joints,
      "axis_mask:", s.axis_mask, "spindles:", s.spindles)
print("unconfigured joint:", s.joint[5]["units"], s.joint[5]["min_position_limit"],
      s.joint[5]["max_position_limit"], s.joint[5]["max_ferror"])
print("ini_filename ends with machine.ini:", s.ini_filename.endswith("machine.ini"))

table = s.tool_table
print("tool_table:", len(table), [t.id for t in table], table[0].id)
print("tool 1 by attribute and index:", table[1].zoffset, table[1][3], table[1].diameter)
print("toolinfo(5):", sorted(s.toolinfo(5).items()))
for bad_tool in (0, 50):
    try:
        s.toolinfo(bad_tool)
    except ValueError as e:
        print("toolinfo(%d): %s" % (bad_tool, e))

beat = s.taskbeat
copy = s.position
import time
time.sleep(0.05)
print("no change without poll:", s.taskbeat == beat)
s.poll()
print("taskbeat advances:", s.taskbeat > beat)


class MyStat(linuxcnc.stat):
    """A subclass, as GUIs make."""

    def machine_on(self):
        """True when on."""
        self.poll()
        return self.task_state == linuxcnc.STATE_ON


print("subclass:", MyStat().machine_on())
