#!/bin/bash
# rs274 -s appends the interpreter's function stack (innermost first) after the error text and line;
# without -s only the two lines are written. -s given twice toggles the stack off again.
echo "== with -s"
rs274 -g -s test.ngc 2>&1 >/dev/null | sed -n '/^Arc radius/,$p'
echo "== without -s"
rs274 -g test.ngc 2>&1 >/dev/null | sed -n '/^Arc radius/,$p'
echo "== -s -s"
rs274 -g -s -s test.ngc 2>&1 >/dev/null | sed -n '/^Arc radius/,$p'
