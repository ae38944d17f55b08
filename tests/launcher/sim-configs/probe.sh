#!/bin/bash
# display for sim-configs: dump the signals and thread functions of the machine just built
name=$(basename "$2" .ini)
halcmd -s show sig > "$name.sigs"
halcmd save thread > "$name.threads"
