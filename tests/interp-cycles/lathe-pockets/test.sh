#!/bin/bash
# G71/G72 with a pocket in the profile: .0 roughs the pocket level by level, .1 bridges it,
# .2 roughs only the pocket; U/W profile moves, A fillets, C chamfers, default I and R.
rs274 -t test.tbl -g test.ngc | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
