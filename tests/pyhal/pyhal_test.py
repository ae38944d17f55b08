"""pyhal_test.py: helpers shared by the pyhal test scripts (halcmd calls, labelled results)."""
import subprocess


def halcmd(*args):
    """Run halcmd and return its stripped stdout."""
    done = subprocess.run(["halcmd"] + list(args), capture_output=True, text=True)
    return done.stdout.strip()


def show(label, func):
    """Print label and the result or the exception raised by func."""
    try:
        result = func()
    except Exception as exc:  # the test records every error text
        result = "%s: %s" % (type(exc).__name__, exc)
    print("%s -> %s" % (label, result))
