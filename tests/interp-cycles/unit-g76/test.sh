#!/bin/bash
# G76 threading: degressive pass depths, compound angle, spring passes, tapers, internal threads, errors.
cd "$(dirname "$0")"
"$EMC2_HOME/objects/unit/cycles_unit" < cases.txt
