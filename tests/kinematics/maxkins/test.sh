#!/bin/bash
# maxkins through the fake-HAL harness: pins and defaults, head and table math, directions.
exec "$EMC2_HOME/objects/unit/comptest" < script
