"""Tokenizer for the declaration part of a .comp file (before the ';;' line)."""

import re


class CompError(Exception):
    """A grammar or semantic error at a position of the .comp file."""

    def __init__(self, msg, line=0, col=None, src_line=None):
        """Remember the message and where it happened (line, column, source text)."""
        super().__init__(msg)
        self.msg = msg
        self.line = line
        self.col = col
        self.src_line = src_line


_STRING_RE = re.compile(r'(r?)("""(?:.|\n)*?"""|"(?:[^"\\\n]|\\.)*")')
_NUMBER_RE = re.compile(
    r'[-+]?(0[xX][0-9a-fA-F]+|0[bB][01]+|0[oO][0-7]+|'
    r'(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?[fF]?)(?![A-Za-z0-9_#.-])')
_NAME_RE = re.compile(r'[#A-Za-z_][-#A-Za-z0-9_.]*')
_PUNCT = '[]=;:*<>(),'


class Token:
    """One lexical token: kind is 'name', 'number', 'string' or 'punct'."""

    def __init__(self, kind, text, value, pos):
        """Remember kind, source text, parsed value and position."""
        self.kind = kind
        self.text = text
        self.value = value
        self.pos = pos

    def __repr__(self):
        """Short form for debugging."""
        return 'Token(%s,%r)' % (self.kind, self.text)


def _unescape(body, raw):
    """Turn the inside of a string literal into its value (C escapes unless raw)."""
    if raw:
        return body
    return re.sub(r'\\(x[0-9a-fA-F]{1,2}|[0-7]{1,3}|.)', _escape_char, body,
                  flags=re.S)


def _escape_char(m):
    """Translate one C escape sequence match."""
    s = m.group(1)
    table = {'n': '\n', 't': '\t', 'r': '\r', 'a': '\a', 'b': '\b',
             'f': '\f', 'v': '\v', '\\': '\\', '"': '"', "'": "'", '\n': ''}
    if s in table:
        return table[s]
    if s[0] == 'x':
        return chr(int(s[1:], 16))
    if s[0] in '01234567':
        return chr(int(s, 8))
    return '\\' + s


class Lexer:
    """Produces tokens from the text, skipping whitespace and comments."""

    def __init__(self, text):
        """Start at the beginning of text."""
        self.text = text
        self.pos = 0

    def line_col(self, pos):
        """1-based line and column of a character offset."""
        line = self.text.count('\n', 0, pos) + 1
        start = self.text.rfind('\n', 0, pos) + 1
        return line, pos - start + 1

    def source_line(self, pos):
        """The text of the line holding pos."""
        start = self.text.rfind('\n', 0, pos) + 1
        end = self.text.find('\n', pos)
        return self.text[start:end if end >= 0 else len(self.text)]

    def error(self, msg, pos):
        """Build a CompError located at pos."""
        line, col = self.line_col(pos)
        return CompError(msg, line, col, self.source_line(pos))

    def skip_blank(self):
        """Advance past whitespace and comments."""
        t = self.text
        while self.pos < len(t):
            if t[self.pos].isspace():
                self.pos += 1
            elif t.startswith('//', self.pos):
                end = t.find('\n', self.pos)
                self.pos = len(t) if end < 0 else end
            elif t.startswith('/*', self.pos):
                end = t.find('*/', self.pos + 2)
                if end < 0:
                    raise self.error('Unterminated comment', self.pos)
                self.pos = end + 2
            else:
                return

    def next(self):
        """Return the next token, or None at end of text."""
        self.skip_blank()
        t, p = self.text, self.pos
        if p >= len(t):
            return None
        m = _STRING_RE.match(t, p)
        if m:
            self.pos = m.end()
            lit = m.group(2)
            body = lit[3:-3] if lit.startswith('"""') else lit[1:-1]
            return Token('string', m.group(0), _unescape(body, bool(m.group(1))), p)
        if t[p] == '"':
            raise self.error('Unterminated string', p)
        m = _NUMBER_RE.match(t, p)
        if m and (t[p] not in '+-' or p + 1 < len(t)):
            self.pos = m.end()
            return Token('number', m.group(0), m.group(0), p)
        m = _NAME_RE.match(t, p)
        if m:
            self.pos = m.end()
            return Token('name', m.group(0), m.group(0), p)
        if t[p] in _PUNCT:
            self.pos = p + 1
            return Token('punct', t[p], t[p], p)
        raise self.error('Unexpected character %r' % t[p], p)

    def raw_until(self, stops):
        """Return raw text up to (not including) the first char in stops at depth 0."""
        t, p, depth = self.text, self.pos, 0
        while p < len(t):
            c = t[p]
            if c == '(':
                depth += 1
            elif c == ')':
                depth -= 1
            elif c in stops and depth <= 0:
                break
            p += 1
        s = t[self.pos:p]
        self.pos = p
        return s.strip()
