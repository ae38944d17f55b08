#!/bin/bash
# preview_helpers and rs274.interpret (see test.py)
python3 test.py
