#!/bin/bash
# rtapi.h in one process: message levels, clock period rules, id counter, shm
# handles, task limits, pause/resume/delete, bit/mutex/string helpers.
"$EMC2_HOME/objects/unit/rtapi_api_test"
