#!/bin/bash
# display of the -k run: which components got loaded
halcmd -s show comp | awk 'NF >= 3 && $2 == "RT" {print $3}' | sort | tr '\n' ' '; echo
