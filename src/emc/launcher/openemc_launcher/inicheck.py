"""inicheck: linuxcnc_check_ini, the consistency checks run before a configuration starts."""
import os

AXIS_LETTERS = "XYZABCUVW"
LINEAR_UNITS = ("mm", "metric", "in", "inch", "imperial")
ANGULAR_UNITS = ("deg", "degree", "grad", "gon", "rad", "radian")
BOOL_WORDS = ("TRUE", "YES", "ON", "1", "FALSE", "NO", "OFF", "0")
HOME_FLAGS = ("HOME_USE_INDEX", "HOME_IGNORE_LIMITS", "HOME_IS_SHARED",
              "HOME_INDEX_NO_ENCODER_RESET")
REAL_KEYS = ("MIN_LIMIT", "MAX_LIMIT", "MAX_VELOCITY", "MAX_ACCELERATION", "MAX_JERK",
             "BACKLASH", "FERROR", "MIN_FERROR", "HOME", "HOME_OFFSET", "HOME_SEARCH_VEL",
             "HOME_LATCH_VEL", "HOME_FINAL_VEL")
AXIS_REAL_KEYS = ("MIN_LIMIT", "MAX_LIMIT", "MAX_VELOCITY", "MAX_ACCELERATION", "MAX_JERK",
                  "OFFSET_AV_RATIO")
RANGED_INTS = (("EMCMOT", "BASE_PERIOD", 0, None), ("EMCMOT", "SERVO_PERIOD", 0, None),
               ("EMCMOT", "TRAJ_PERIOD", 0, None), ("TRAJ", "SPINDLES", 0, 8),
               ("TRAJ", "PLANNER_TYPE", 0, 1))
JOINT_INTS = (("COMP_FILE_TYPE", 0, 1), ("HOME_ABSOLUTE_ENCODER", 0, 2),
              ("HOME_SEQUENCE", None, None))
DEFAULT_LIMIT = 1e99


def parse_int(text):
    """An integer as the INI library reads it (sign, then decimal, 0x, 0o, 0b or leading-0 octal)."""
    word = text.split()[0]
    sign, digits = (-1, word[1:]) if word[:1] == "-" else (1, word.lstrip("+"))
    if len(digits) > 1 and digits[0] == "0" and digits[1].isdigit():
        return sign * int(digits, 8)
    return sign * int(digits, 0)


class StopChecking(Exception):
    """A fault that makes the remaining checks meaningless ([KINS] missing or invalid)."""


class IniChecker:
    """Runs every check on one parsed INI file and collects (level, text) messages."""

    def __init__(self, ini, path):
        """ini: a parsed INI object (_linuxcnc_ini.ini); path: its file name for messages."""
        self.ini, self.path = ini, path
        self.messages = []

    def say(self, level, text, section=None, key=None, num=1):
        """Record one message; the entry's line is appended when known."""
        if section is not None:
            text += self.where(section, key, num)
        self.messages.append((level, text))

    def where(self, section, key, num=1):
        """' (line N)' (or ' (file F line N)' for an #INCLUDEd file) of an entry, '' if absent."""
        path, line = self.ini.lineof(section, key, num)
        if line is None:
            return ""
        if os.path.realpath(path) != os.path.realpath(self.path):
            return " (file %s line %d)" % (path, line)
        return " (line %d)" % line

    def integer(self, section, key, low, high, required=False):
        """Check an integer entry and its range; returns its value or None."""
        text = self.ini.find(section, key)
        if text is None:
            if required:
                self.say("error", "[%s]%s: Missing" % (section, key))
            return None
        try:
            value = parse_int(text) if text.strip() else None
        except ValueError:
            value = None
        if value is None:
            self.say("error", "[%s]%s: Invalid integer value '%s'" % (section, key, text),
                     section, key)
        elif (low is not None and value < low) or (high is not None and value > high):
            bounds = "[%s,%s]" % ("..." if low is None else low, "..." if high is None else high)
            self.say("error", "[%s]%s: Integer value '%s' out of range %s"
                     % (section, key, text, bounds), section, key)
            return None
        return value

    def real(self, section, key):
        """Check a real-number entry; returns its value or None (missing or invalid)."""
        text = self.ini.find(section, key)
        if text is None:
            return None
        try:
            return float(text.split()[0])
        except (ValueError, IndexError):
            self.say("error", "[%s]%s: Invalid number '%s'" % (section, key, text), section, key)
            return None

    def enum(self, section, key, choices, required=False):
        """Check a word entry against choices (case-insensitive)."""
        text = self.ini.find(section, key)
        if text is None:
            if required:
                self.say("error", "[%s]%s: Missing" % (section, key))
        elif text.lower() not in [c.lower() for c in choices]:
            self.say("error", "[%s]%s: Must be one of [%s] (found '%s')"
                     % (section, key, ",".join(choices), text), section, key)

    def boolean(self, section, key):
        """Check a strict boolean entry."""
        text = self.ini.find(section, key)
        if text is not None and text.upper() not in BOOL_WORDS:
            self.say("error", "[%s]%s: Invalid boolean value '%s' (use one of %s)"
                     % (section, key, text, " ".join(BOOL_WORDS)), section, key)

    def duplicates(self, section):
        """Warn about keys given more than once in a section."""
        seen = {}
        for key, value in self.ini.getvariables(section):
            seen.setdefault(key, []).append(value)
        for key, values in seen.items():
            if len(values) > 1:
                self.say("warning", "[%s]%s: Duplicate entry found, values: %s"
                         % (section, key, values), section, key, 2)

    def kinematics(self):
        """[KINS]KINEMATICS and JOINTS; returns (module, coordinates or None, joints)."""
        kins = self.ini.find("KINS", "KINEMATICS")
        if not kins or not kins.split():
            self.say("error", "[KINS]KINEMATICS: Missing")
            raise StopChecking()
        joints = self.integer("KINS", "JOINTS", 0, 16, required=True)
        if joints is None:
            raise StopChecking()
        module, coordinates = kins.split()[0], None
        for arg in kins.split()[1:]:
            name, eq, value = arg.partition("=")
            if not eq:
                self.say("error", "[KINS]KINEMATICS: Invalid argument '%s' (expected name=value)"
                         % arg, "KINS", "KINEMATICS")
            elif name == "coordinates":
                coordinates = self.coordinates_option(value)
        return module, coordinates, joints

    def coordinates_option(self, value):
        """Axis letters of a coordinates= option (upper case); bad letters are errors."""
        letters = value.replace(" ", "").upper()
        for letter in letters:
            if letter not in AXIS_LETTERS:
                self.say("error", "[KINS]KINEMATICS: Invalid axis '%s' in kinematics coordinates "
                         "option" % letter, "KINS", "KINEMATICS")
        return letters

    def units_and_ranges(self):
        """Units, ranged integers and the [TRAJ]/[EMCMOT] values."""
        self.enum("TRAJ", "LINEAR_UNITS", LINEAR_UNITS, required=True)
        self.enum("TRAJ", "ANGULAR_UNITS", ANGULAR_UNITS, required=True)
        for section, key, low, high in RANGED_INTS:
            self.integer(section, key, low, high)
        for key in ("NO_FORCE_HOMING",):
            self.boolean("TRAJ", key)

    def joint(self, n):
        """Types, numbers, booleans and duplicates of [JOINT_n]."""
        section = "JOINT_%d" % n
        self.enum(section, "TYPE", ("LINEAR", "ANGULAR"))
        for key in HOME_FLAGS:
            self.boolean(section, key)
        for key, low, high in JOINT_INTS:
            self.integer(section, key, low, high)
        for key in REAL_KEYS:
            self.real(section, key)
        self.duplicates(section)

    def axis(self, letter):
        """Types, numbers and duplicates of [AXIS_L]."""
        section = "AXIS_%s" % letter
        self.enum(section, "TYPE", ("LINEAR", "ANGULAR"))
        for key in AXIS_REAL_KEYS:
            self.real(section, key)
        self.boolean(section, "WRAPPED_ROTARY")
        self.duplicates(section)

    def limit(self, section, key, default):
        """(value, text) of a limit entry; the default when it is absent or invalid."""
        text = self.ini.find(section, key)
        try:
            return float(text.split()[0]), text.split()[0]
        except (AttributeError, ValueError, IndexError):
            return default, repr(default)

    def nesting(self, joint, letter):
        """trivkins: the axis limits must lie within the joint limits."""
        jsec, asec = "JOINT_%d" % joint, "AXIS_%s" % letter
        jmax, jmax_t = self.limit(jsec, "MAX_LIMIT", DEFAULT_LIMIT)
        amax, amax_t = self.limit(asec, "MAX_LIMIT", DEFAULT_LIMIT)
        jmin, jmin_t = self.limit(jsec, "MIN_LIMIT", -DEFAULT_LIMIT)
        amin, amin_t = self.limit(asec, "MIN_LIMIT", -DEFAULT_LIMIT)
        if jmax < amax:
            self.say("error", "[%s]MAX_LIMIT < [%s]MAX_LIMIT (%s < %s)"
                     % (jsec, asec, jmax_t, amax_t), jsec, "MAX_LIMIT")
        if jmin > amin:
            self.say("error", "[%s]MIN_LIMIT > [%s]MIN_LIMIT (%s > %s)"
                     % (jsec, asec, jmin_t, amin_t), jsec, "MIN_LIMIT")

    def unspecified(self, section, default_note):
        """Warn when MAX_VELOCITY or MAX_ACCELERATION of a section is not given."""
        for key in ("MAX_VELOCITY", "MAX_ACCELERATION"):
            if self.ini.find(section, key) is None:
                self.say("warning", "[%s]%s: Unspecified, default used (%s)"
                         % (section, key, default_note))

    def trivkins(self, coordinates, joints):
        """Joint/axis pairing of trivkins: limits nest, velocities given, coordinates agree."""
        letters = coordinates if coordinates is not None else AXIS_LETTERS[:joints]
        traj = (self.ini.find("TRAJ", "COORDINATES") or "").replace(" ", "").upper()
        if coordinates is not None and traj and coordinates != traj:
            self.say("warning", "[KINS]KINEMATICS coordinates=%s differs from "
                     "[TRAJ]COORDINATES=%s" % (coordinates, traj), "KINS", "KINEMATICS")
        for joint, letter in enumerate(letters[:joints]):
            if letter in AXIS_LETTERS:
                self.nesting(joint, letter)
            self.unspecified("JOINT_%d" % joint, "1.0")
        for letter in sorted(set(letters) & set(AXIS_LETTERS), key=AXIS_LETTERS.index):
            self.unspecified("AXIS_%s" % letter, "1.0")

    def run(self):
        """Every check; returns the messages as (level, text)."""
        try:
            module, coordinates, joints = self.kinematics()
        except StopChecking:
            return self.messages
        self.units_and_ranges()
        for n in range(joints):
            self.joint(n)
        traj = (self.ini.find("TRAJ", "COORDINATES") or "").replace(" ", "").upper()
        for letter in sorted(set(traj) & set(AXIS_LETTERS), key=AXIS_LETTERS.index):
            self.axis(letter)
        if module == "trivkins":
            self.trivkins(coordinates, joints)
        else:
            self.say("info", "[KINS]KINEMATICS=%s: joint and axis limits not cross-checked "
                     "(only trivkins is)" % module)
        return self.messages


def check(ini, path, warnings_fatal=False, out=None):
    """Print the messages as '<path>: level: text'; True when the configuration may start."""
    import sys
    out = out or sys.stderr
    messages = IniChecker(ini, path).run()
    for level, text in messages:
        out.write("%s: %s: %s\n" % (path, level, text))
    fatal = ("error", "warning") if warnings_fatal else ("error",)
    return not any(level in fatal for level, _ in messages)
