#!/usr/bin/env python3
"""fake_broker.py: a minimal MQTT 3.1.1 broker for one client; logs CONNECT and PUBLISH packets."""
import socket
import sys

CONNECT, CONNACK, PUBLISH, PINGREQ, PINGRESP, DISCONNECT = 1, 2, 3, 12, 13, 14


def read_exact(conn, n):
    """n bytes from the connection, or None at its end."""
    data = b""
    while len(data) < n:
        chunk = conn.recv(n - len(data))
        if not chunk:
            return None
        data += chunk
    return data


def read_packet(conn):
    """(type, flags, body) of the next packet, or None at the end of the connection."""
    head = read_exact(conn, 1)
    if head is None:
        return None
    length, shift = 0, 0
    while True:
        byte = read_exact(conn, 1)
        if byte is None:
            return None
        length |= (byte[0] & 0x7F) << shift
        shift += 7
        if not byte[0] & 0x80:
            break
    body = read_exact(conn, length) if length else b""
    return head[0] >> 4, head[0] & 0x0F, body


def string_at(body, pos):
    """The length-prefixed string at pos and the position after it."""
    n = int.from_bytes(body[pos:pos + 2], "big")
    return body[pos + 2:pos + 2 + n].decode(), pos + 2 + n


def log_connect(body, log):
    """Log the protocol, the client id and the user of a CONNECT."""
    proto, pos = string_at(body, 0)
    flags = body[pos + 1]
    client_id, pos = string_at(body, pos + 4)
    user = string_at(body, pos)[0] if flags & 0x80 else "-"
    log.write("CONNECT %s user=%s\n" % (proto, user))


def serve(conn, log):
    """Answer one client until it disconnects."""
    while True:
        packet = read_packet(conn)
        if packet is None:
            return
        kind, flags, body = packet
        if kind == CONNECT:
            log_connect(body, log)
            conn.sendall(bytes([CONNACK << 4, 2, 0, 0]))
        elif kind == PUBLISH:
            topic, pos = string_at(body, 0)
            pos += 2 if flags & 0x06 else 0
            log.write("PUBLISH %s %s\n" % (topic, body[pos:].decode()))
        elif kind == PINGREQ:
            conn.sendall(bytes([PINGRESP << 4, 0]))
        elif kind == DISCONNECT:
            return
        log.flush()


def main():
    """Listen on a free port, print it, serve one client, log to argv[1]."""
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(1)
    print(server.getsockname()[1], flush=True)
    conn, _ = server.accept()
    with open(sys.argv[1], "w") as log:
        serve(conn, log)


if __name__ == "__main__":
    main()
