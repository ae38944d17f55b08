"""C code generation: module parameters, entry points and item macros."""

MAX_PERSONALITIES = 64
# Instance names a userspace component takes with names= (an array, as LinuxCNC's)
MAX_USER_NAMES = 16


def gen_modparams(comp, out):
    """count/names/personality module parameters and user modparams."""
    rt = not comp.userspace
    unused = ' __attribute__((unused))'
    if rt:
        lic = comp.license.replace('\\', '\\\\').replace('"', '\\"')
        out.append('MODULE_LICENSE("%s");' % lic)
    if not comp.singleton and comp.option('rtapi_app') is not False:
        dc = comp.options.get('default_count', '1')
        out.append('static int default_count%s = %s;' % (unused, dc))
        out.append('static int count%s = 0;' % unused)
        if rt and not comp.option('count_function'):
            out.append('RTAPI_MP_INT(count, "number of %s");' % comp.name)
        if rt:
            out.append('static char *names%s = "";' % unused)
        else:
            out.append('static char *names[%d]%s = {0};' % (MAX_USER_NAMES, unused))
        if rt:
            out.append('RTAPI_MP_STRING(names, "names of %s");' % comp.name)
    if comp.uses_personality:
        dp = comp.options.get('default_personality', '0')
        out.append('static int personality[%d]%s = { [0 ... %d] = %s };'
                   % (MAX_PERSONALITIES, unused, MAX_PERSONALITIES - 1, dp))
        if rt:
            out.append('RTAPI_MP_ARRAY_INT(personality, %d, "personality of each %s");'
                       % (MAX_PERSONALITIES, comp.name))
    for mp in comp.modparams:
        if mp.type == 'dummy':
            continue
        out.append('static int %s%s = %s;' % (mp.cname, unused, mp.default or '0'))
        doc = (mp.doc or '').replace('\\', '\\\\').replace('"', '\\"').replace('\n', ' ')
        if rt:
            out.append('RTAPI_MP_INT(%s, "%s");' % (mp.cname, doc))
    out.append('')


def export_args(comp, index):
    """Arguments after prefix for an export() call of instance `index`."""
    if comp.uses_personality:
        return '%s, personality[(%s) %% %d]' % (index, index, MAX_PERSONALITIES)
    return index


def gen_pers_note(comp, out, pad):
    """Print the personality note for an instance index beyond the array."""
    if comp.uses_personality:
        out.append(pad + 'if (i >= %d) rtapi_print_msg(RTAPI_MSG_INFO, "%s: name %%s '
                   'assigned personality=%%d(=0x%%x)\\n", buf, personality[i %% %d], '
                   'personality[i %% %d]);' % (MAX_PERSONALITIES, comp.name,
                                                MAX_PERSONALITIES, MAX_PERSONALITIES))


def gen_export_call(comp, out, pad):
    """Export instance i named buf, returning from the loop function on failure."""
    gen_pers_note(comp, out, pad)
    out.append(pad + 'r = export(buf, %s);' % export_args(comp, 'i'))
    out.append(pad + 'if (r != 0) return r;')


def gen_user_names_loop(comp, out):
    """Userspace: create one instance per entry of the names[] array main() filled."""
    out.append('static int __comp_export_names(void) {')
    out.append('    char buf[HAL_NAME_LEN + 1];')
    out.append('    int i, r;')
    out.append('    for (i = 0; i < %d && names[i]; i++) {' % MAX_USER_NAMES)
    out.append('        if (strlen(names[i]) > HAL_NAME_LEN) {')
    out.append('            rtapi_print_msg(RTAPI_MSG_ERR, "names: \\"%s\\" too long\\n", names[i]);')
    out.append('            return -EINVAL;')
    out.append('        }')
    out.append('        rtapi_snprintf(buf, sizeof(buf), "%s", names[i]);')
    gen_export_call(comp, out, '        ')
    out.append('    }')
    out.append('    return 0;')
    out.append('}')
    out.append('')


def gen_names_loop(comp, out):
    """Create one instance per comma-separated entry of names=."""
    if comp.userspace:
        gen_user_names_loop(comp, out)
        return
    out.append('static int __comp_export_names(void) {')
    out.append('    char buf[HAL_NAME_LEN + 1];')
    out.append('    int i = 0, r = 0;')
    out.append('    size_t j = 0, k;')
    out.append('    for (k = 0; ; k++) {')
    out.append("        if (names[k] == ',' || names[k] == '\\0') {")
    out.append("            buf[j] = '\\0';")
    out.append('            if (j == 0) {')
    out.append('                rtapi_print_msg(RTAPI_MSG_ERR, "names[%d] is invalid (empty string)\\n", i);')
    out.append('                return -EINVAL;')
    out.append('            }')
    gen_export_call(comp, out, '            ')
    out.append("            if (names[k] == '\\0') break;")
    out.append('            j = 0;')
    out.append('            i++;')
    out.append('        } else {')
    out.append('            if (j >= HAL_NAME_LEN) {')
    out.append('                size_t e = k;')
    out.append("                while (names[e] && names[e] != ',') e++;")
    out.append('                rtapi_print_msg(RTAPI_MSG_ERR, "names: \\"%.*s\\" too long\\n", '
               '(int)(e - k + j), names + k - j);')
    out.append('                return -EINVAL;')
    out.append('            }')
    out.append('            if ((unsigned char)names[k] <= \' \' || names[k] == 0x7f) {')
    out.append('                rtapi_print_msg(RTAPI_MSG_ERR, "names[%d] contains a blank or control '
               'character\\n", i);')
    out.append('                return -EINVAL;')
    out.append('            }')
    out.append('            buf[j++] = names[k];')
    out.append('        }')
    out.append('    }')
    out.append('    return 0;')
    out.append('}')
    out.append('')


def gen_count_loop(comp, out):
    """Create `n` instances named <comp>.<i>."""
    out.append('static int __comp_export_count(int n) {')
    out.append('    char buf[HAL_NAME_LEN + 1];')
    out.append('    int i, r;')
    out.append('    for (i = 0; i < n; i++) {')
    out.append('        rtapi_snprintf(buf, sizeof(buf), "%s.%%d", i);' % comp.prefix_base)
    gen_export_call(comp, out, '        ')
    out.append('    }')
    out.append('    return 0;')
    out.append('}')
    out.append('')


def gen_count_function_check(comp, out):
    """With count_function, names= must match get_count() and have no empty names."""
    out.append('static int __comp_check_names(int n) {')
    out.append('    int c = 1, i = 0, start = 0;')
    out.append('    size_t k;')
    out.append('    for (k = 0; ; k++) {')
    out.append("        if (names[k] == ',' || names[k] == '\\0') {")
    out.append('            if ((int)k == start) {')
    out.append('                rtapi_print_msg(RTAPI_MSG_ERR, "names[%d] is invalid (empty string)\\n", i);')
    out.append('                return -EINVAL;')
    out.append('            }')
    out.append("            if (names[k] == '\\0') break;")
    out.append('            c++; i++; start = k + 1;')
    out.append('        }')
    out.append('    }')
    out.append('    if (c != n) {')
    out.append('        rtapi_print_msg(RTAPI_MSG_ERR, "names= count (%%d) does not match %s '
               'count (%%d)\\n", c, n);' % comp.name)
    out.append('        return -EINVAL;')
    out.append('    }')
    out.append('    return 0;')
    out.append('}')
    out.append('')


def gen_create_instances(comp, out):
    """Body of the instance-creation step shared by RT and userspace main."""
    if comp.singleton:
        out.append('    r = export("%s", 0%s);' % (
            comp.prefix_base, ', personality[0]' if comp.uses_personality else ''))
        return
    if comp.option('count_function') and comp.userspace:
        out.append('    r = __comp_export_count(get_count());')
        return
    if comp.option('count_function'):
        out.append('    if (names[0]) {')
        out.append('        r = __comp_check_names(get_count());')
        out.append('        if (r == 0) r = __comp_export_names();')
        out.append('    } else {')
        out.append('        r = __comp_export_count(get_count());')
        out.append('    }')
        return
    # Unlike the reference, a bad combination still reaches hal_exit (no stale comp).
    out.append('    if (count && names[0]) {')
    out.append('        rtapi_print_msg(RTAPI_MSG_ERR, "count= and names= are mutually exclusive\\n");')
    out.append('        r = -EINVAL;')
    out.append('    } else if (count < 0) {')
    out.append('        rtapi_print_msg(RTAPI_MSG_ERR, "count=%d: the count must not be negative\\n", count);')
    out.append('        r = -EINVAL;')
    out.append('    } else {')
    out.append('        if (!count && !names[0]) count = default_count;')
    out.append('        if (count) r = __comp_export_count(count);')
    out.append('        else r = __comp_export_names();')
    out.append('    }')


def gen_app_main(comp, out):
    """rtapi_app_main and rtapi_app_exit."""
    if comp.option('count_function'):
        out.append('int get_count(void);')
    if comp.option('constructable') and not comp.userspace:
        out.append('static int __comp_construct(char *prefix, char *arg) {')
        out.append('    (void)arg;')
        out.append('    return export(prefix, 0%s);' % (
            ', 0' if comp.uses_personality else ''))
        out.append('}')
    out.append('int rtapi_app_main(void) {')
    out.append('    int r = 0;')
    out.append('    comp_id = hal_init("%s");' % comp.name)
    out.append('    if (comp_id < 0) return comp_id;')
    gen_create_instances(comp, out)
    out.append('    if (r) {')
    if comp.option('extra_cleanup'):
        out.append('        extra_cleanup();')
    out.append('        hal_exit(comp_id);')
    out.append('        return r;')
    out.append('    }')
    if comp.option('constructable') and not comp.userspace:
        out.append('    hal_set_constructor(comp_id, __comp_construct);')
    out.append('    hal_ready(comp_id);')
    out.append('    return 0;')
    out.append('}')
    out.append('')
    out.append('void rtapi_app_exit(void) {')
    if comp.option('extra_cleanup'):
        out.append('    extra_cleanup();')
    out.append('    hal_exit(comp_id);')
    out.append('}')
    out.append('')


# C helper of a userspace main(): remove "key<value>" from argv, returning the value.
TAKE_ARG_C = """\
static int __comp_take_arg(int *argc, char **argv, const char *key, char **val) {
    int i, n = strlen(key);
    for (i = 1; i < *argc; i++) {
        if (strncmp(argv[i], key, n) == 0) {
            *val = argv[i] + n;
            for (; i < *argc; i++) argv[i] = argv[i + 1];
            (*argc)--;
            return 1;
        }
    }
    return 0;
}"""


def gen_user_main(comp, out):
    """main() of a userspace component."""
    out.append('void user_mainloop(void);')
    if comp.option('userinit'):
        out.append('void userinit(int argc, char **argv);')
    out.extend(TAKE_ARG_C.split('\n'))
    out.append('int main(int argc, char **argv) {')
    out.append('    char *v;')
    if not comp.singleton:
        out.append('    int has_count = __comp_take_arg(&argc, argv, "count=", &v);')
        out.append('    if (has_count) count = atoi(v);')
        out.append('    if (__comp_take_arg(&argc, argv, "names=", &v)) {')
        if comp.option('count_function'):
            out.append('        fprintf(stderr, "names= is not supported with count_function\\n");')
            out.append('        return 1;')
        else:
            out.append('        int n = 0;')
            out.append('        if (has_count) {')
            out.append('            fprintf(stderr, "count= and names= are mutually exclusive\\n");')
            out.append('            return 1;')
            out.append('        }')
            out.append('        for (v = strtok(v, ","); v; v = strtok(NULL, ",")) {')
            out.append('            if (n == %d) {' % MAX_USER_NAMES)
            out.append('                fprintf(stderr, "names=: at most %d names\\n");' % MAX_USER_NAMES)
            out.append('                return 1;')
            out.append('            }')
            out.append('            names[n++] = v;')
            out.append('        }')
        out.append('    }')
    else:
        out.append('    (void)v;')
    if comp.option('userinit'):
        out.append('    userinit(argc, argv);')
    out.append('    if (rtapi_app_main() < 0) return 1;')
    out.append('    user_mainloop();')
    out.append('    rtapi_app_exit();')
    out.append('    return 0;')
    out.append('}')
    out.append('')


def gen_entry_points(comp, out):
    """Module parameters, instance loops and entry points."""
    gen_modparams(comp, out)
    if comp.option('rtapi_app') is False:
        return
    if not comp.singleton:
        gen_count_loop(comp, out)
        gen_names_loop(comp, out)
        if comp.option('count_function') and not comp.userspace:
            gen_count_function_check(comp, out)
    gen_app_main(comp, out)
    if comp.userspace:
        gen_user_main(comp, out)
