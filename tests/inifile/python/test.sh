# python: the Python ini type (module _linuxcnc_ini, re-exported as linuxcnc.ini), diagnostics included.
python3 -u bindings.py 2>&1
