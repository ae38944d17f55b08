#!/usr/bin/env python3
"""hal_manualtoolchange: ask the operator to change the tool when iocontrol asks for a change.

Pins: hal_manualtoolchange.number (s32 in), .change (bit in), .change_button (bit in),
.changed (bit out). While `change` is TRUE the operator is asked to insert tool `number`: in a
Tk dialog (wish) when there is an X display, else on the controlling terminal; `change_button`
confirms as well. With neither a display nor a terminal the change is confirmed at once, with
a note on stderr. When `change` drops, `changed` drops and an open question is withdrawn.
"""
import os
import shutil
import subprocess
import sys
import threading
import time

import hal

POLL_S = 0.05
DIALOG = """
wm title . "Tool change"
label .msg -text {Insert tool %d and click continue when ready} -padx 20 -pady 10
button .ok -text Continue -command {puts ok; exit 0}
pack .msg .ok -pady 5
wm protocol . WM_DELETE_WINDOW {exit 1}
"""


class Question:
    """One pending request to the operator; done() is True once it was answered."""

    def __init__(self, tool):
        """Ask for tool in a dialog, on the terminal, or nowhere (answered at once)."""
        self.answered = threading.Event()
        self.proc = None
        wish = shutil.which("wish")
        if os.environ.get("DISPLAY") and wish:
            self.proc = subprocess.Popen([wish], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                         text=True)
            self.proc.stdin.write(DIALOG % tool)
            self.proc.stdin.close()
            threading.Thread(target=self._wait_dialog, daemon=True).start()
        elif self._ask_terminal(tool):
            pass
        else:
            sys.stderr.write("hal_manualtoolchange: no display or terminal to ask on; "
                             "tool %d is taken as inserted\n" % tool)
            self.answered.set()

    def _wait_dialog(self):
        """Answered when the dialog printed ok."""
        if self.proc.stdout.readline().strip() == "ok":
            self.answered.set()

    def _ask_terminal(self, tool):
        """Prompt on /dev/tty in a thread; False when there is no terminal."""
        try:
            tty = open("/dev/tty", "r+")
        except OSError:
            return False
        tty.write("hal_manualtoolchange: insert tool %d and press Enter\n" % tool)
        tty.flush()

        def wait():
            """Answered on Enter."""
            if tty.readline():
                self.answered.set()
        threading.Thread(target=wait, daemon=True).start()
        return True

    def withdraw(self):
        """The change was cancelled: close the dialog."""
        if self.proc and self.proc.poll() is None:
            self.proc.terminate()


def main():
    """Serve tool changes until SIGTERM."""
    if sys.argv[1:2] in (["--help"], ["-h"]):
        sys.stdout.write("Usage: loadusr hal_manualtoolchange\n" + __doc__.split("\n", 2)[2])
        return 0
    comp = hal.component("hal_manualtoolchange")
    comp.newpin("number", hal.HAL_S32, hal.HAL_IN)
    comp.newpin("change", hal.HAL_BIT, hal.HAL_IN)
    comp.newpin("change_button", hal.HAL_BIT, hal.HAL_IN)
    comp.newpin("changed", hal.HAL_BIT, hal.HAL_OUT)
    comp.ready()
    question = None
    try:
        while True:
            if comp["change"] and not comp["changed"]:
                if question is None:
                    question = Question(comp["number"])
                if question.answered.is_set() or comp["change_button"]:
                    comp["changed"] = True
                    question = None
            elif not comp["change"]:
                comp["changed"] = False
                if question is not None:
                    question.withdraw()
                    question = None
            time.sleep(POLL_S)
    except KeyboardInterrupt:
        if question is not None:
            question.withdraw()
    return 0


if __name__ == "__main__":
    sys.exit(main())
