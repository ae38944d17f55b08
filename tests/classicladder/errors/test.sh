#!/bin/bash
# Bad projects: each is refused with the file, the line (when there is one) and the problem.
cd "$(dirname "$0")"
{
    for f in *.clp; do
        echo "load $f"
    done
    echo "load missing.clp"
} | "$EMC2_HOME/objects/unit/cl_sim"
