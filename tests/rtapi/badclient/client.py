#!/usr/bin/env python3
"""client.py: misbehaving rtapi_app clients (partial requests, bad lengths, early close)."""
import os
import socket
import struct
import sys
import time


def socket_name():
    """Abstract socket name of this instance's master, as librtapi builds it."""
    name = os.environ.get("RTAPI_FIFO_PATH") or os.path.join(os.environ["HOME"], ".rtapi_fifo")
    inst = int(os.environ.get("OPENEMC_INSTANCE", "0"))
    return "\0" + name + ("." + str(inst) if inst else "")


def send_and_close(label, data):
    """Connect, send data, close without reading; print what was done."""
    s = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    s.connect(socket_name())
    s.sendall(data)
    s.close()
    print("sent %s" % label)


def request(*args):
    """A well-formed request for args."""
    body = b"".join(struct.pack("<H", len(a)) + a.encode() for a in args)
    return struct.pack("<HH", 4 + len(body), len(args)) + body


def hold(flag):
    """Send half a request, tell the test through flag, then stay silent."""
    s = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    s.connect(socket_name())
    s.sendall(request("list")[:5])
    open(flag, "w").close()
    time.sleep(60)


if len(sys.argv) == 3 and sys.argv[1] == "hold":
    hold(sys.argv[2])
    sys.exit(0)

full = request("load", "rtapi_test_params", "count=9")
send_and_close("nothing", b"")
send_and_close("one byte", b"\x10")
send_and_close("half a request", full[: len(full) // 2])
send_and_close("length too small", struct.pack("<HH", 3, 0))
send_and_close("argc beyond data", struct.pack("<HH", 6, 40) + b"\x00\x00")
send_and_close("arg length beyond data", struct.pack("<HHH", 8, 1, 900) + b"ab")
send_and_close("full request, reply never read", request("ping"))
