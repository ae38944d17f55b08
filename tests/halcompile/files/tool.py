#!/usr/bin/env python2
"""tool.py: a Python userspace component installed by halcompile --install."""
print("tool ran")
