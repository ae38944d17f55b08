# shmleak: a HAL segment a test leaves behind (key XORed with its instance) is reported and removed.
. "$TEST_DIR/../lib.sh"
fixture a-leaks 'python3 "$TEST_DIR/../mkshm.py" "$TEST_DIR/../key" && echo ok' ok
cat > "$TREE/mkshm.py" <<'PY'
import ctypes, os, sys
key = 0x48414C32 ^ (int(os.environ["OPENEMC_INSTANCE"]) << 24)
open(sys.argv[1], "w").write("0x%08x\n" % key)
shmid = ctypes.CDLL(None).shmget(ctypes.c_int(key - (1 << 32) if key >= 1 << 31 else key), 4096, 0o1600)
sys.exit(0 if shmid >= 0 else 1)
PY
run_runner . > "$WORK/report"
sed "s/$(cat "$TREE/key")/KEY/" "$WORK/report"
key=$(( $(cat "$TREE/key") ))
if awk -v k="$key" 'NR > 1 && ($1 == k || $1 + 4294967296 == k) { found = 1 } END { exit !found }' /proc/sysvipc/shm
then echo "segment still there"; else echo "segment removed"; fi
