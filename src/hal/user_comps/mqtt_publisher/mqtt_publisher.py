#!/usr/bin/env python3
"""mqtt-publisher: a HAL user component that publishes HAL values to an MQTT broker periodically."""
import json
import os
import signal
import sys
import time

import hal

USAGE = """Usage: loadusr -W mqtt-publisher [options] keys=NAME[,NAME...]
Publishes the values of the named HAL pins, signals or parameters as one JSON object
(the names are its keys) to an MQTT broker every mqtt-publisher.period seconds.
  keys=NAME[,NAME...]     what to publish (no blanks after the commas)
  --dryrun                print each message on stdout instead of connecting
  --mqtt-broker=HOST      broker host name (default localhost)
  --mqtt-port=N           broker port (default 1883)
  --mqtt-user=USER        user name for the broker
  --mqtt-password=PASS    password for the broker
  --mqtt-prefix=TOPIC     topic to publish to (default devices/linuxcnc/machine)
  --help                  this text
Pins: mqtt-publisher.enable (bit in, default TRUE), mqtt-publisher.period (u32 in, seconds,
default 10), mqtt-publisher.lastpublish (u32 out, seconds since the epoch, 0 before the first).
"""

DEFAULTS = {"broker": "localhost", "port": 1883, "user": None, "password": None,
            "prefix": "devices/linuxcnc/machine", "dryrun": False, "keys": []}
POLL_S = 0.05         # how often enable/period are looked at (s)
DEBIAN_PYTHON = "/usr/lib/python3/dist-packages"   # python3-paho-mqtt installs here


class UsageError(Exception):
    """A bad command line: printed with the program name, exit status 1."""


def parse_args(argv):
    """Return the settings dict of a command line; raises UsageError."""
    opts = dict(DEFAULTS)
    value_options = {"--mqtt-broker": "broker", "--mqtt-port": "port", "--mqtt-user": "user",
                     "--mqtt-password": "password", "--mqtt-prefix": "prefix"}
    for arg in argv:
        name, eq, value = arg.partition("=")
        if arg == "--dryrun":
            opts["dryrun"] = True
        elif name == "keys" and eq:
            opts["keys"] = [k for k in value.split(",") if k]
        elif name in value_options and eq:
            opts[value_options[name]] = value
        else:
            raise UsageError("unknown argument '%s'" % arg)
    if not opts["keys"]:
        raise UsageError("no keys=NAME[,NAME...] given")
    try:
        opts["port"] = int(opts["port"])
    except ValueError:
        raise UsageError("--mqtt-port needs a number, not '%s'" % opts["port"]) from None
    if not 0 < opts["port"] < 65536:
        raise UsageError("--mqtt-port %d is not a port number" % opts["port"])
    return opts


def import_paho():
    """The paho MQTT client module, also when Debian's package is outside this Python's path."""
    try:
        import paho.mqtt.client as client
    except ImportError:
        if DEBIAN_PYTHON in sys.path or not os.path.isdir(DEBIAN_PYTHON):
            raise
        sys.path.append(DEBIAN_PYTHON)
        import paho.mqtt.client as client
    return client


class Publisher:
    """Reads the keys from HAL and sends them to the broker (or stdout with --dryrun)."""

    def __init__(self, opts):
        self.opts = opts
        self.missing = set()   # keys already reported as not found
        self.client = None
        if not opts["dryrun"]:
            self.client = self.connect()

    def connect(self):
        """Connect to the broker; the network loop runs in paho's own thread."""
        try:
            paho = import_paho()
        except ImportError:
            raise UsageError("the Python module paho.mqtt is missing (Debian package "
                             "python3-paho-mqtt)") from None
        client = paho.Client()
        if self.opts["user"]:
            client.username_pw_set(self.opts["user"], self.opts["password"])
        try:
            client.connect(self.opts["broker"], self.opts["port"])
        except OSError as e:
            raise UsageError("cannot connect to MQTT broker %s:%d: %s"
                             % (self.opts["broker"], self.opts["port"], e)) from None
        client.loop_start()
        return client

    def values(self):
        """The current value of every key that exists; a missing one is reported once."""
        found = {}
        for key in self.opts["keys"]:
            try:
                found[key] = hal.get_value(key)
            except Exception:
                if key not in self.missing:
                    sys.stderr.write("mqtt-publisher: '%s' is not a HAL pin, signal or "
                                     "parameter; left out\n" % key)
                    self.missing.add(key)
        return found

    def publish(self):
        """Send one message with all values."""
        message = json.dumps(self.values())
        if self.client is None:
            print(message, flush=True)
        else:
            self.client.publish(self.opts["prefix"], message)

    def close(self):
        """Disconnect from the broker."""
        if self.client is not None:
            self.client.loop_stop()
            self.client.disconnect()


def make_component():
    """Create the HAL component with its pins and defaults."""
    comp = hal.component("mqtt-publisher")
    comp.newpin("enable", hal.HAL_BIT, hal.HAL_IN)
    comp.newpin("period", hal.HAL_U32, hal.HAL_IN)
    comp.newpin("lastpublish", hal.HAL_U32, hal.HAL_OUT)
    comp["enable"] = True
    comp["period"] = 10
    comp.ready()
    return comp


def run(comp, publisher, stop):
    """Publish at once, then whenever `period` seconds (as the pin says now) have passed since
    the last message, while enabled. Messages keep to the period's grid (no drift from the
    polling) unless a whole period was missed."""
    last_at = None
    while not stop:
        now = time.monotonic()
        period = max(comp["period"], 1)
        due = last_at is None or now - last_at >= period
        if comp["enable"] and due:
            publisher.publish()
            comp["lastpublish"] = int(time.time())
            last_at = now if last_at is None or now - last_at >= 2 * period else last_at + period
        time.sleep(POLL_S)


def main(argv):
    """Parse the command line, create the component, publish until SIGTERM or SIGINT."""
    if argv[:1] in (["--help"], ["-h"]):
        sys.stdout.write(USAGE)
        return 0
    stop = []
    try:
        opts = parse_args(argv)
        publisher = Publisher(opts)
    except UsageError as e:
        sys.stderr.write("mqtt-publisher: %s\n" % e)
        return 1
    comp = make_component()
    for sig in (signal.SIGTERM, signal.SIGINT):
        signal.signal(sig, lambda *_: stop.append(True))
    try:
        run(comp, publisher, stop)
    finally:
        publisher.close()
        comp.exit()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
