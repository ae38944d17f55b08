"""rshclient.py: a linuxcncrsh client for the tests. A request's replies are collected by
sending 'get plat' after it and reading up to its reply, so no test waits a fixed time.

As a program: 'wait-status' waits for task's status, 'wait-port PORT' for linuxcncrsh."""
import os
import socket
import sys
import time

TIMEOUT_S = 20.0
MARKERS = ("PLAT Linux", "GET PLAT NAK")


class Session:
    """One TCP connection to linuxcncrsh."""

    def __init__(self, port=None, host="127.0.0.1"):
        self.port = int(port or os.environ["RSH_PORT"])
        self.sock = socket.create_connection((host, self.port), timeout=TIMEOUT_S)
        self.buf = b""

    def line(self):
        """The next reply line (without \\r\\n); None when the server closed."""
        while b"\r\n" not in self.buf:
            data = self.sock.recv(4096)
            if not data:
                return None
            self.buf += data
        text, self.buf = self.buf.split(b"\r\n", 1)
        return text.decode()

    def send(self, text):
        self.sock.sendall((text + "\n").encode())

    def ask(self, text):
        """Send text and return its reply lines (the echo of the marker removed)."""
        self.send(text)
        self.send("get plat")
        out = []
        while True:
            line = self.line()
            if line is None:
                out.append("<closed>")
                return out
            if line in MARKERS:
                if out and out[-1] == "get plat":
                    out.pop()
                return out
            out.append(line)

    def show(self, text):
        """Print the request and its replies."""
        print("> " + text)
        for line in self.ask(text):
            print("  " + line)

    def closed(self):
        """True when the server closed the connection (after what was sent so far)."""
        try:
            while True:
                data = self.sock.recv(4096)
                if not data:
                    return True
                self.buf += data
        except (ConnectionResetError, socket.timeout):
            return False

    def close(self):
        self.sock.close()


def wait_status():
    """Wait until task (or the responder) publishes status."""
    import linuxcnc
    s = linuxcnc.stat()
    end = time.time() + TIMEOUT_S
    while time.time() < end:
        try:
            s.poll()
            if s.taskbeat > 0:
                return 0
        except linuxcnc.error:
            pass
        time.sleep(0.02)
    sys.stderr.write("machine did not start\n")
    return 1


def wait_port(port):
    """Wait until a connection to port succeeds."""
    end = time.time() + TIMEOUT_S
    while time.time() < end:
        try:
            socket.create_connection(("127.0.0.1", int(port)), timeout=1).close()
            return 0
        except OSError:
            time.sleep(0.02)
    sys.stderr.write("linuxcncrsh did not listen on port %s\n" % port)
    return 1


if __name__ == "__main__":
    if sys.argv[1] == "wait-status":
        sys.exit(wait_status())
    sys.exit(wait_port(sys.argv[2]))
