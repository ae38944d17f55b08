#!/bin/bash
# scorbot-kins through the fake-HAL harness: pinless, type BOTH, arm poses by hand, out-of-reach refused.
exec "$EMC2_HOME/objects/unit/comptest" < script
