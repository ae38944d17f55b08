"""errors: the exception that stops a launch with a message for the operator."""


class LaunchError(Exception):
    """A start-up step failed; the message names the file, line and what is wrong."""

    def __init__(self, message, status=1):
        """message is printed on stderr as it is; status becomes the exit status."""
        super().__init__(message)
        self.status = status


class Interrupted(Exception):
    """SIGINT, SIGTERM or SIGHUP arrived; the launcher cleans up and exits."""

    def __init__(self, signum):
        """signum is the signal that arrived."""
        super().__init__("signal %d" % signum)
        self.signum = signum
