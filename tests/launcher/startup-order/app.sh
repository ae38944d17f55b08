#!/bin/bash
# an [APPLICATIONS] program: records that it ran, then stays until stopped
echo "app: $*" > app-ran.txt
exec sleep 60
