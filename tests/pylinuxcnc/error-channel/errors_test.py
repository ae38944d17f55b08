"""errors_test.py: the error channel is one queue: each message to exactly one reader, in order."""
import subprocess
import linuxcnc

c = linuxcnc.command()
a = linuxcnc.error_channel()
b = linuxcnc.error_channel()
while a.poll():
    pass

for i in range(6):
    c.text_msg("message %d" % i)
c.wait_complete()
got_a = [a.poll(), a.poll()]
got_b = [b.poll(), b.poll()]
child = subprocess.run(["python3", "-c",
                        "import linuxcnc; e = linuxcnc.error_channel(); print(e.poll()); print(e.poll())"],
                       capture_output=True, text=True, check=True)
print("reader a:", got_a)
print("reader b:", got_b)
print("another process:", child.stdout.split("\n")[:2])
print("then empty:", a.poll(), b.poll())

c.error_msg("an error")
c.text_msg("a text")
c.display_msg("a display")
c.wait_complete()
print("kinds:", [a.poll() for _ in range(3)])
print("constants:", linuxcnc.OPERATOR_ERROR, linuxcnc.OPERATOR_TEXT, linuxcnc.OPERATOR_DISPLAY)
