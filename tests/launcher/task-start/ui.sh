#!/bin/bash
# display: says it ran
echo "display ran"
