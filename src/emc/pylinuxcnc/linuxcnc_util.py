"""linuxcnc_util: helpers test scripts use to wait for a running machine (hallib.md sec. 3)."""

import math
import sys
import time

import linuxcnc

AXIS_LETTERS = "xyzabcuvw"


def axis_index(letter):
    """Index 0..8 of an axis letter (XYZABCUVW, either case); ValueError for others."""
    return AXIS_LETTERS.index(letter.lower())


class LinuxCNC_Exception(Exception):
    """Raised when the machine does not reach an expected state in time."""


class LinuxCNC:
    """A command channel, a status channel and an error channel, with waits on them."""

    def __init__(self, command=None, status=None, error=None):
        """Use the given channel objects, or make new ones for those not given."""
        self.command = command or linuxcnc.command()
        self.status = status or linuxcnc.stat()
        self.error = error or linuxcnc.error_channel()

    def wait_for_linuxcnc_startup(self, timeout=10.0):
        """Return once task reports a configured, idle machine in E-stop; RuntimeError on timeout."""
        start = time.time()
        while time.time() - start < timeout:
            self.status.poll()
            s = self.status
            if (s.angular_units != 0 and s.axis_mask != 0 and s.cycle_time != 0
                    and s.exec_state == linuxcnc.EXEC_DONE
                    and s.interp_state == linuxcnc.INTERP_IDLE and s.inpos
                    and s.linear_units != 0 and s.max_acceleration != 0
                    and s.max_velocity != 0 and s.program_units != 0 and s.rapidrate != 0
                    and s.state == linuxcnc.RCS_DONE
                    and s.task_state == linuxcnc.STATE_ESTOP):
                return
            time.sleep(0.1)
        raise RuntimeError()

    def all_joints_homed(self, joints):
        """True when every joint i with a true joints[i] (i < 9) is homed."""
        self.status.poll()
        for i in range(9):
            if joints[i] and not self.status.homed[i]:
                return False
        return True

    def wait_for_home(self, joints, timeout=10.0):
        """Wait until the given joints are homed."""
        start = time.time()
        while time.time() - start < timeout:
            if self.all_joints_homed(joints):
                return
            time.sleep(0.1)
        self.status.poll()
        raise LinuxCNC_Exception("timeout waiting for homing to complete:\nstatus.homed:"
                                 + str(self.status.homed) + "\nstatus.position:"
                                 + str(self.status.position))

    def wait_for_axis_to_stop(self, axis_letter, timeout=10.0):
        """Wait until the commanded position of an axis stops changing."""
        print("waiting for axis %s to stop" % axis_letter)
        index = axis_index(axis_letter)
        self.status.poll()
        prev = self.status.position[index]
        start = time.time()
        while time.time() - start < timeout:
            time.sleep(0.1)
            self.status.poll()
            pos = self.status.position[index]
            if pos == prev:
                return
            prev = pos
        raise LinuxCNC_Exception(
            "axis %s didn't stop jogging!\n" % axis_letter
            + "axis %s is at %.3f %.3f seconds after reaching target (prev_pos=%.3f)\n"
            % (axis_letter, pos, timeout, prev))

    def jog_axis(self, axis_letter, target, vel=5.0, timeout=10.0):
        """Jog one axis (teleop) past target, stop it, and check no other axis moved."""
        index = axis_index(axis_letter)
        self.status.poll()
        start_pos = list(self.status.position)
        pos = start_pos[index]
        print("jogging axis %s from %.3f to %.3f" % (axis_letter, pos, target))
        if pos < target:
            speed = math.fabs(vel)
            done = lambda p: p > target
        else:
            speed = -math.fabs(vel)
            done = lambda p: p < target
        self.command.jog(linuxcnc.JOG_CONTINUOUS, 0, index, speed)
        start = time.time()
        reached = False
        while time.time() - start < timeout:
            self.status.poll()
            pos = self.status.position[index]
            if done(pos):
                reached = True
                break
            time.sleep(0.1)
        self.command.jog(linuxcnc.JOG_STOP, 0, index)
        if not reached:
            raise LinuxCNC_Exception("failed to jog axis %s to %.3f\n" % (axis_letter, target)
                                     + "timed out at %.3f after %.3f seconds" % (pos, timeout))
        print("    jogged axis %d past target %.3f" % (index, target))
        self.wait_for_axis_to_stop(axis_letter)
        self.status.poll()
        for i, letter in enumerate(AXIS_LETTERS):
            if i != index and self.status.position[i] != start_pos[i]:
                raise LinuxCNC_Exception("axis %s moved from %.3f to %.3f but should not have!"
                                         % (letter, start_pos[i], self.status.position[i]))

    def wait_for_axis_to_stop_at(self, axis_letter, target, timeout=10.0, tolerance=0.0001):
        """Wait until an axis stands still within tolerance of target."""
        index = axis_index(axis_letter)
        self.status.poll()
        start = time.time()
        pos = vel = 0.0
        while time.time() - start < timeout:
            prev = self.status.position[index]
            self.status.poll()
            pos = self.status.position[index]
            vel = pos - prev
            if math.fabs(pos - target) < tolerance and vel == 0:
                print("axis %s stopped at %.3f" % (axis_letter, target))
                return
            time.sleep(0.1)
        raise LinuxCNC_Exception("timeout waiting for axis %s to stop at %.3f (pos=%.3f, vel=%.3f)"
                                 % (axis_letter, target, pos, vel))

    def wait_for_interp_state(self, target_state, timeout=10.0):
        """Wait until the interpreter reaches target_state (polled every millisecond).

        On timeout LinuxCNC's helper fails with AttributeError (it formats its message from an
        attribute that does not exist); scripts may rely on that, so the same happens here."""
        start = time.time()
        while time.time() - start < timeout:
            self.status.poll()
            if self.status.interp_state == target_state:
                return
            time.sleep(0.001)
        raise AttributeError("'LinuxCNC' object has no attribute 'interp_state' (interpreter "
                             "state %d did not reach target state %d)"
                             % (self.status.interp_state, target_state))

    def wait_for_tool_in_spindle(self, expected_tool, timeout=10.0):
        """Wait until the status reports expected_tool in the spindle."""
        start = time.time()
        while time.time() - start < timeout:
            time.sleep(0.1)
            self.status.poll()
            if self.status.tool_in_spindle == expected_tool:
                print("the Stat buffer's toolInSpindle reached the value of %d after %f seconds"
                      % (expected_tool, time.time() - start))
                return
        raise LinuxCNC_Exception("the Stat buffer's toolInSpindle value is %d, expected %d"
                                 % (self.status.tool_in_spindle, expected_tool))


if __name__ == "__main__":
    sys.stderr.write("linuxcnc_util is a module; import it from a test script\n")
    sys.exit(1)
