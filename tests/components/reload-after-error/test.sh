#!/bin/bash
# Loads that fail after hal_init (count= with names=) must leave no stale component:
# the same module loads again at once, show comp lists only live comps, unload all works.
halrun -k -f reload.hal 2>&1 | grep -v -e '^Note:' -e 'waitpid failed' -e 'without becoming ready'
echo "exit ${PIPESTATUS[0]}"
