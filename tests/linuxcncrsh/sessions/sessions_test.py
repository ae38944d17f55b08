"""sessions_test.py: control, session limit, failed HELLOs and shutdown with two clients."""
from rshclient import Session


def both(a, b, req):
    """The same request from a and from b."""
    print("A", end="")
    a.show(req)
    print("B", end="")
    b.show(req)


a = Session()
b = Session()
for s in (a, b):
    s.ask("hello EMC client 1.0")
    s.ask("set echo off")
    s.ask("set verbose on")
print("== A takes control")
a.show("set enable EMCTOO")
both(a, b, "get enable")
print("B", end="")
b.show("set estop off")
print("== B takes it over")
b.show("set enable EMCTOO")
both(a, b, "get enable")
print("A", end="")
a.show("set estop off")
print("== a third connection is refused (--sessions 2)")
c = Session()
print("C", c.line())
print("C closed:", c.closed())
print("== B gives control back and leaves; a new session may connect")
b.show("set enable off")
both(a, b, "get enable")
b.send("quit")
print("B closed:", b.closed())
d = Session()
print("== three wrong HELLOs close the connection")
for _ in range(3):
    d.send("hello guess me")
    print("D", d.line())
print("D closed:", d.closed())
e = Session()
e.ask("hello EMC client")
e.ask("set echo off")
print("== shutdown without control is refused")
print("E", end="")
e.show("shutdown")
print("== shutdown from A (in control)")
a.show("set enable EMCTOO")
a.send("shutdown")
print("A closed:", a.closed(), "E closed:", e.closed())
