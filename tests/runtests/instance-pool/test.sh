# instance-pool: runtests skips instances whose shared memory or rtapi_app socket exists, and
# falls back to a per-user lock directory when the shared one is unusable.
exec python3 "$TEST_DIR/pool.py"
