#!/bin/bash
# Drive the component with the fake-HAL harness; stdout is compared with expected.
exec "$EMC2_HOME/objects/unit/comptest" < script
