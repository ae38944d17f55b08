component lcd "Stream formatted HAL values to a character LCD, one byte per call (Mesa 7i73 LCD port)";
pin out u32 out "Byte to send to the display this call (connect to the 7i73 lcd pin); 0 when there is nothing to send";
pin in float contrast "Display contrast, 0 to 1; a change is sent as ESC C and a byte 0..255 at the next refresh";
param rw u32 decimal_separator = 46 "Character used as the decimal point of f and F conversions (46 is '.')";
variable hal_u32_t *page_pin;
variable struct lcd_page *pages;
variable int n_pages;
variable int cur_page = -1;
variable int started;
variable int cursor;
variable int arg_no;
variable int buf_len;
variable int buf_pos;
variable double last_contrast;
variable unsigned char buf[48];
modparam dummy fmt_strings "Format strings: one per display separated by ',', pages of a display separated by '|'";
option rtapi_app no;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
description """Load with fmt_strings="DISPLAY0,DISPLAY1,..." where each display is PAGE0|PAGE1|...
Display N has pins lcd.NN.out, lcd.NN.page_num (u32 IN, with an underscore as in LinuxCNC: the
page to show counting from 0; a page that does not exist blanks the display), lcd.NN.contrast,
param lcd.NN.decimal-separator (NN two digits), and one input pin lcd.NN.page.PP.arg.AA per conversion of page PP. One funct,
lcd, updates every display and may run in a floating-point thread.

The page is sent again and again: the display is cleared (byte 0x1A) before the first refresh of a
page and the cursor sent home (byte 0x1E) before every other refresh; a changed contrast is sent
(ESC 'C' value) before that. Text is sent as it is, with these escapes: \\n clears to the end
of the line (ESC 'T') then sends CR and LF; \\t sends a TAB; \\HH sends the byte with hex value
HH (use \\2C for ',' and \\7C for '|'); \\\\ sends a backslash; %% sends '%'.

Conversions are %[flags][width][.precision]C. Flags: '0' pads with zeros, '+' shows the sign of
positive numbers, ' ' puts a space before them. The width is strict: a value that does not fit
is shown as width asterisks. C is f or F (float pin, precision 6 by default, decimal point from
decimal-separator), d or i (s32 pin), u, x, X or o (u32 pin, decimal, hex, upper-case hex,
octal), c (u32 pin sent as a character) or b followed by two characters (bit pin: the first is
shown when TRUE, the second when FALSE). Values are read when their conversion is reached; halfway values
round away from zero and a value that rounds to zero shows no minus sign. A new page_num or
contrast takes effect at the next refresh. count= and names= are not accepted.""";
;;
#define LCD_MAX_WIDTH 40
#define LCD_CLEAR 0x1a
#define LCD_HOME 0x1e
#define LCD_ESC 0x1b
#define F_ZERO 1
#define F_PLUS 2
#define F_SPACE 4

enum { TOK_BYTES, TOK_CONV };
enum { ERR_ESCAPE = 1, ERR_CONV, ERR_WIDTH, ERR_PREC, ERR_BOOL };
static const char *tok_errors[] = {
    "", "bad escape (\\n, \\t, \\\\ or \\HH with two hex digits)",
    "bad conversion (f, F, d, i, u, x, X, o, c or b)", "width above 40", "precision above 9",
    "b conversion needs two characters after it",
};

union lcd_pin {
    hal_float_t *f;
    hal_s32_t *s;
    hal_u32_t *u;
    hal_bit_t *b;
};

struct lcd_page {
    char *text;
    int n_args;
    union lcd_pin *args;
};

struct lcd_tok {
    int kind;
    int len;
    unsigned char bytes[4];
    int n_bytes;
    int flags;
    int width;
    int prec;
    char conv;
    char true_ch;
    char false_ch;
};

static char *fmt_strings;
RTAPI_MP_STRING(fmt_strings, "format strings of the displays");

/* Value of a hex digit, or -1. */
static int hex_value(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/* Parse a backslash escape at s into t; returns the length or -ERR_ESCAPE. */
static int parse_escape(const char *s, struct lcd_tok *t)
{
    static const unsigned char newline[4] = { LCD_ESC, 'T', '\r', '\n' };
    t->kind = TOK_BYTES;
    t->n_bytes = 1;
    if (s[1] == 'n') {
        memcpy(t->bytes, newline, 4);
        t->n_bytes = 4;
        return 2;
    }
    if (s[1] == 't' || s[1] == '\\') {
        t->bytes[0] = s[1] == 't' ? '\t' : '\\';
        return 2;
    }
    if (hex_value(s[1]) < 0 || hex_value(s[2]) < 0) return -ERR_ESCAPE;
    t->bytes[0] = (unsigned char)(hex_value(s[1]) * 16 + hex_value(s[2]));
    return 3;
}

/* Parse a decimal number of at most three digits at s; returns the digits used. */
static int parse_number(const char *s, int *value)
{
    int n = 0;
    *value = 0;
    while (s[n] >= '0' && s[n] <= '9' && n < 3) *value = *value * 10 + (s[n++] - '0');
    return n;
}

/* Parse a % conversion at s into t; returns the length or a negative error. */
static int parse_conv(const char *s, struct lcd_tok *t)
{
    int n = 1;
    for (;; n++) {
        if (s[n] == '0') t->flags |= F_ZERO;
        else if (s[n] == '+') t->flags |= F_PLUS;
        else if (s[n] == ' ') t->flags |= F_SPACE;
        else break;
    }
    n += parse_number(s + n, &t->width);
    if (t->width > LCD_MAX_WIDTH) return -ERR_WIDTH;
    if (s[n] == '.') {
        n++;
        n += parse_number(s + n, &t->prec);
        if (t->prec > 9) return -ERR_PREC;
    }
    t->conv = s[n];
    if (!t->conv || !strchr("fFdiuxXocb", t->conv)) return -ERR_CONV;
    if (t->conv == 'b') {
        if (!s[n + 1] || !s[n + 2]) return -ERR_BOOL;
        t->true_ch = s[n + 1];
        t->false_ch = s[n + 2];
        n += 2;
    }
    t->kind = TOK_CONV;
    return n + 1;
}

/* Parse the token at s (text, escape or conversion); returns its length or a negative error. */
static int parse_token(const char *s, struct lcd_tok *t)
{
    memset(t, 0, sizeof(*t));
    t->prec = -1;
    if (s[0] == '\\') return parse_escape(s, t);
    if (s[0] == '%' && s[1] == '%') {
        t->bytes[0] = '%';
        t->n_bytes = 1;
        return 2;
    }
    if (s[0] == '%') return parse_conv(s, t);
    t->bytes[0] = (unsigned char)s[0];
    t->n_bytes = 1;
    return 1;
}

/* Sign character of a number: '-', or '+'/' ' for positive values per the flags, or none. */
static char sign_char(const struct lcd_tok *t, int negative)
{
    if (negative) return '-';
    if (t->flags & F_PLUS) return '+';
    if (t->flags & F_SPACE) return ' ';
    return 0;
}

/* Write v in base into digits, most significant first, at least min_digits long. */
static int to_digits(unsigned long long v, unsigned base, int upper, int min_digits, char *digits)
{
    const char *set = upper ? "0123456789ABCDEF" : "0123456789abcdef";
    char rev[24];
    int n = 0, i;
    do {
        rev[n++] = set[v % base];
        v /= base;
    } while (v);
    while (n < min_digits && n < 22) rev[n++] = '0';
    for (i = 0; i < n; i++) digits[i] = rev[n - 1 - i];
    return n;
}

/* Width asterisks (one when no width): the value does not fit. */
static int stars(const struct lcd_tok *t, unsigned char *dst)
{
    int n = t->width ? t->width : 1;
    memset(dst, '*', n);
    return n;
}

/* Sign and digits padded to the width (zeros after the sign with the 0 flag). */
static int assemble(const struct lcd_tok *t, char sign, const char *digits, int n_digits,
                    unsigned char *dst)
{
    int len = n_digits + (sign != 0), pad = t->width > len ? t->width - len : 0, n = 0;
    if (t->width && len > t->width) return stars(t, dst);
    if (!(t->flags & F_ZERO)) for (; n < pad; n++) dst[n] = ' ';
    if (sign) dst[n++] = sign;
    if (t->flags & F_ZERO) for (len = 0; len < pad; len++) dst[n++] = '0';
    memcpy(dst + n, digits, n_digits);
    return n + n_digits;
}

/* Fixed-point text of a float conversion, with dp as the decimal point. */
static int format_float(const struct lcd_tok *t, double v, unsigned dp, unsigned char *dst)
{
    static const double pow10[10] = { 1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9 };
    int prec = t->prec < 0 ? 6 : t->prec, n;
    double mag = fabs(v) * pow10[prec] + 0.5;
    unsigned long long whole, p10 = (unsigned long long)pow10[prec];
    char digits[40];
    if (!(mag < 1.8e19)) return stars(t, dst);
    whole = (unsigned long long)mag;
    n = to_digits(whole / p10, 10, 0, 1, digits);
    if (prec) {
        digits[n++] = (char)dp;
        n += to_digits(whole % p10, 10, 0, prec, digits + n);
    }
    return assemble(t, sign_char(t, v < 0 && whole), digits, n, dst);
}

/* Text of one conversion reading its pin; returns the byte count. */
static int format_conv(const struct lcd_tok *t, const union lcd_pin *pin, unsigned dp,
                       unsigned char *dst)
{
    struct lcd_tok plain = *t;
    char digits[40];
    int min = t->prec > 0 ? t->prec : 1;
    long long s;
    plain.flags = 0;
    switch (t->conv) {
    case 'f': case 'F':
        return format_float(t, *pin->f, dp, dst);
    case 'd': case 'i':
        s = *pin->s;
        return assemble(t, sign_char(t, s < 0), digits,
                        to_digits(s < 0 ? -s : s, 10, 0, min, digits), dst);
    case 'c':
        digits[0] = (char)(*pin->u & 0xff);
        return assemble(&plain, 0, digits, 1, dst);
    case 'b':
        digits[0] = *pin->b ? t->true_ch : t->false_ch;
        return assemble(&plain, 0, digits, 1, dst);
    default:
        return assemble(t, 0, digits, to_digits(*pin->u, t->conv == 'o' ? 8 : t->conv == 'u' ? 10 : 16,
                                                t->conv == 'X', min, digits), dst);
    }
}

/* Contrast 0..1 as the byte sent after ESC C. */
static unsigned char contrast_byte(double c)
{
    if (!(c > 0)) return 0;
    if (c > 1) return 255;
    return (unsigned char)(c * 255 + 0.5);
}

/* Control bytes that begin a refresh: changed contrast, then clear (new page) or home. */
static void start_refresh(struct __comp_state *__comp_inst)
{
    int want = *page_pin < (hal_u32_t)n_pages ? (int)*page_pin : n_pages;
    buf_len = 0;
    buf_pos = 0;
    double c = contrast == contrast ? contrast : 0.0;  /* NaN counts as 0 */
    if (c != last_contrast) {
        buf[buf_len++] = LCD_ESC;
        buf[buf_len++] = 'C';
        buf[buf_len++] = contrast_byte(c);
        last_contrast = c;
    }
    if (!started || want != cur_page) buf[buf_len++] = LCD_CLEAR;
    else if (want < n_pages) buf[buf_len++] = LCD_HOME;
    started = 1;
    cur_page = want;
    cursor = 0;
    arg_no = 0;
}

/* Bytes of the next token of the page into buf. */
static void next_token(struct __comp_state *__comp_inst)
{
    struct lcd_page *pg = &pages[cur_page];
    struct lcd_tok t;
    int len = parse_token(pg->text + cursor, &t);
    buf_pos = 0;
    buf_len = 0;
    if (len <= 0) {
        cursor = (int)strlen(pg->text);
        return;
    }
    cursor += len;
    if (t.kind == TOK_BYTES) {
        memcpy(buf, t.bytes, t.n_bytes);
        buf_len = t.n_bytes;
    } else if (arg_no < pg->n_args) {
        buf_len = format_conv(&t, &pg->args[arg_no++], decimal_separator, buf);
    }
}

/* One byte of one display. */
static void lcd_step(struct __comp_state *__comp_inst)
{
    if (buf_pos >= buf_len) {
        if (started && cur_page < n_pages && pages[cur_page].text[cursor])
            next_token(__comp_inst);
        else
            start_refresh(__comp_inst);
    }
    out = buf_pos < buf_len ? buf[buf_pos++] : 0;
}

/* Funct lcd: every display. */
static void lcd_update(void *arg, long period)
{
    (void)arg;
    (void)period;
    FOR_ALL_INSTS() lcd_step(__comp_inst);
}

/* Count the conversions of a page, checking its syntax; a negative error sets *err_at. */
static int count_args(const char *text, int *err_at)
{
    struct lcd_tok t;
    int pos = 0, n = 0, len;
    while (text[pos]) {
        len = parse_token(text + pos, &t);
        if (len < 0) {
            *err_at = pos;
            return len;
        }
        n += t.kind == TOK_CONV;
        pos += len;
    }
    return n;
}

/* Create the input pin of conversion a of a page, typed by the conversion. */
static int make_pin(const struct lcd_tok *t, union lcd_pin *pin, const char *prefix, int page, int a)
{
#define ARG_NAME "%s.page.%02d.arg.%02d", prefix, page, a
    if (t->conv == 'f' || t->conv == 'F') return hal_pin_float_newf(HAL_IN, &pin->f, comp_id, ARG_NAME);
    if (t->conv == 'd' || t->conv == 'i') return hal_pin_s32_newf(HAL_IN, &pin->s, comp_id, ARG_NAME);
    if (t->conv == 'b') return hal_pin_bit_newf(HAL_IN, &pin->b, comp_id, ARG_NAME);
    return hal_pin_u32_newf(HAL_IN, &pin->u, comp_id, ARG_NAME);
#undef ARG_NAME
}

/* Create the argument pins of a page. */
static int make_args(struct lcd_page *pg, const char *prefix, int page)
{
    struct lcd_tok t;
    int pos = 0, a = 0, r = 0;
    pg->args = hal_malloc(sizeof(union lcd_pin) * (pg->n_args ? pg->n_args : 1));
    if (!pg->args) return -ENOMEM;
    while (pg->text[pos] && r == 0) {
        pos += parse_token(pg->text + pos, &t);
        if (t.kind == TOK_CONV) {
            r = make_pin(&t, &pg->args[a], prefix, page, a);
            a++;
        }
    }
    return r;
}

/* Split one display's text into pages (in place), check them and create their pins. */
static int setup_display(struct __comp_state *__comp_inst, char *text, const char *prefix, int no)
{
    int p, r, err_at = 0;
    r = hal_pin_u32_newf(HAL_IN, &page_pin, comp_id, "%s.page_num", prefix);
    if (r) return r;
    char *c;
    n_pages = 1;
    for (c = text; *c; c++) n_pages += *c == '|';
    pages = hal_malloc(n_pages * sizeof(struct lcd_page));
    if (!pages) return -ENOMEM;
    for (p = 0; p < n_pages; p++) {
        pages[p].text = text;
        c = strchr(text, '|');
        if (c) *c = '\0';
        text = c ? c + 1 : text;
        r = count_args(pages[p].text, &err_at);
        if (r < 0) {
            rtapi_print_msg(RTAPI_MSG_ERR, "lcd: display %d page %d: %s at \"%s\"\n", no, p,
                            tok_errors[-r], pages[p].text + err_at);
            return -EINVAL;
        }
        pages[p].n_args = r;
        r = make_args(&pages[p], prefix, p);
        if (r) return r;
    }
    return 0;
}

/* Create the displays of fmt_strings and the funct. */
static int setup_all(char *text)
{
    char prefix[HAL_NAME_LEN + 1], *c;
    int no, r = 0;
    for (no = 0; text && r == 0; no++) {
        c = strchr(text, ',');
        if (c) *c = '\0';
        rtapi_snprintf(prefix, sizeof(prefix), "lcd.%02d", no);
        r = export(prefix, no);
        if (r == 0) r = setup_display(__comp_last_inst, text, prefix, no);
        text = c ? c + 1 : NULL;
    }
    if (r == 0) r = hal_export_funct("lcd", lcd_update, 0, 1, 0, comp_id);
    return r;
}

/* Load: check fmt_strings, then build every display. */
int rtapi_app_main(void)
{
    char *copy;
    int r;
    if (!fmt_strings || !fmt_strings[0]) {
        rtapi_print_msg(RTAPI_MSG_ERR,
                        "lcd: fmt_strings= is required (displays separated by ',', pages by '|')\n");
        return -EINVAL;
    }
    comp_id = hal_init("lcd");
    if (comp_id < 0) return comp_id;
    copy = hal_malloc(strlen(fmt_strings) + 1);
    r = copy ? 0 : -ENOMEM;
    if (copy) {
        strcpy(copy, fmt_strings);
        r = setup_all(copy);
    }
    if (r) {
        hal_exit(comp_id);
        return r;
    }
    hal_ready(comp_id);
    return 0;
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    hal_exit(comp_id);
}
