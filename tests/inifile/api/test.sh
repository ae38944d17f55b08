# api: the C++ and C APIs of the INI library (typed reads, lists, errors), diagnostics included.
"$EMC2_HOME/objects/unit/inifile_api" typed.ini broken.ini 2>&1 | sed "s|$PWD/||"
