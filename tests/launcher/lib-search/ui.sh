#!/bin/bash
# display: which instances the HAL files made
halcmd -s show comp | awk 'NF >= 3 && $2 == "RT" {print $3}' | sort | tr '\n' ' '; echo
halcmd -s show funct | awk '{print $NF}' | grep -v '^$' | sort | tr '\n' ' '; echo
