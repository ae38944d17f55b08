#!/bin/bash
# Expression evaluator: precedence, functions, comparisons, parameters and error texts.
cd "$(dirname "$0")"
"$EMC2_HOME/objects/unit/rs274_expr" < cases.txt
