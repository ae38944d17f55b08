#!/bin/sh
echo "say.sh: $*"
