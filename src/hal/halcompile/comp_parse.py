"""Parser of .comp declarations into a Component model."""

import os
import re

from .comp_lexer import CompError, Lexer
from .comp_model import Component, Item, TYPE_MAP



def split_comp(text):
    """Split file text at the first ';;' line: (declarations, C code, C start line)."""
    if text.startswith(';;\n'):
        return '', text[3:], 2
    idx = text.find('\n;;\n')
    if idx < 0:
        if text.endswith('\n;;'):
            return text[:-3], '', text.count('\n') + 1
        return text, '', text.count('\n') + 2
    decl = text[:idx + 1]
    return decl, text[idx + 4:], decl.count('\n') + 2


class Parser:
    """Recursive-descent parser over the Lexer's tokens."""

    def __init__(self, text, comp):
        """Parse text into comp, reading the first token."""
        self.lex = Lexer(text)
        self.comp = comp
        self.tok = self.lex.next()

    def error(self, msg, tok=None):
        """CompError at tok (or the current token / end of text)."""
        pos = tok.pos if tok else (self.tok.pos if self.tok else len(self.lex.text))
        return self.lex.error(msg, pos)

    def err_at(self, tok):
        """A function building a CompError located at tok."""
        return lambda msg: self.error(msg, tok)

    def advance(self):
        """Consume the current token and return it."""
        t = self.tok
        self.tok = self.lex.next()
        return t

    def peek_is(self, text):
        """True if the current token is the punct/name text."""
        return self.tok is not None and self.tok.kind != 'string' and \
            self.tok.text == text

    def expect(self, kind, text=None, what=None):
        """Consume a token of kind (and text) or raise."""
        t = self.tok
        if t is None or t.kind != kind or (text is not None and t.text != text):
            want = what or (repr(text) if text else kind)
            got = 'end of file' if t is None else repr(t.text)
            raise self.error('Expected %s, got %s' % (want, got))
        return self.advance()

    def expect_cname(self, what='name'):
        """Consume a C identifier."""
        t = self.expect('name', what=what)
        if not re.match(r'^[A-Za-z_][A-Za-z0-9_]*$', t.text):
            raise self.error('Invalid %s %r' % (what, t.text), t)
        return t

    def opt_string(self):
        """Consume an optional string literal; return its value or None."""
        if self.tok is not None and self.tok.kind == 'string':
            return self.advance().value
        return None

    def end(self):
        """Expect the terminating ';'."""
        self.expect('punct', ';', "';'")

    def parse(self):
        """Parse all declarations."""
        first = True
        while self.tok is not None:
            t = self.expect('name', what='declaration')
            if first and t.text != 'component':
                raise self.error("Expected 'component', got %r" % t.text, t)
            if not first and t.text == 'component':
                raise self.error('Duplicate component declaration', t)
            first = False
            handler = getattr(self, 'decl_' + t.text, None)
            if handler is None:
                raise self.error('Unknown declaration %r' % t.text, t)
            handler(t)
        if first:
            raise self.error("Expected 'component', got end of file")

    def decl_component(self, t):
        """component NAME ["doc"];"""
        self.comp.name = self.expect_cname('component name').text
        self.comp.doc = self.opt_string()
        self.end()

    def parse_type(self):
        """A HAL type keyword mapped to its classic name and new-API flag."""
        t = self.expect('name', what='type')
        if t.text not in TYPE_MAP:
            raise self.error('Unknown type %r' % t.text, t)
        return TYPE_MAP[t.text]

    def int_token(self, what):
        """Consume an integer literal (decimal, 0x, 0o, 0b) and return its value."""
        t = self.expect('number', what=what)
        try:
            value = int(t.text, 0)
        except ValueError:
            raise self.error('Invalid %s %r' % (what, t.text), t)
        if value < 1:
            raise self.error('Invalid %s %r' % (what, t.text), t)
        return value

    def parse_array(self):
        """Optional [N] or [MAX : EXPR]; returns (size or None, expr or None)."""
        if not self.peek_is('['):
            return None, None
        self.advance()
        size = self.int_token('array size')
        expr = None
        if self.peek_is(':'):
            self.advance()
            if self.tok is None:
                raise self.error("Expected ']'")
            self.lex.pos = self.tok.pos
            expr = self.lex.raw_until(']')
            self.tok = self.lex.next()
        self.expect('punct', ']', "']'")
        return size, expr

    def parse_default(self):
        """Optional '= VALUE' (number or identifier token)."""
        if not self.peek_is('='):
            return None
        self.advance()
        t = self.tok
        if t is None or t.kind not in ('number', 'name'):
            raise self.error('Expected default value')
        return self.advance().text

    def parse_cond(self):
        """Optional 'if COND' (raw C text up to a string or ';')."""
        if not self.peek_is('if'):
            return None
        self.lex.pos = self.tok.pos + 2
        cond = self.lex.raw_until('";')
        self.tok = self.lex.next()
        if not cond:
            raise self.error('Expected condition after if')
        return cond

    def item_common(self, kind, t, direction):
        """Shared tail of pin and param declarations."""
        htype, newapi = self.parse_type()
        name_tok = self.expect('name', what='item name')
        size, expr = self.parse_array()
        item = Item(kind, name_tok.text, htype, direction, newapi=newapi,
                    size=size, size_expr=expr, line=t.pos)
        item.default = self.parse_default()
        item.cond = self.parse_cond()
        item.doc = self.opt_string()
        self.check_array_name(item, name_tok)
        self.end()
        self.comp.add_item(item, self.err_at(name_tok))

    def check_array_name(self, item, tok):
        """Array names need exactly one '#' run; scalars none."""
        runs = re.findall('#+', item.name)
        if item.size is not None and not runs:
            raise self.error("Array name contains no #: %r" % item.name, self.tok)
        if len(runs) > 1:
            raise self.error("Array name contains more than one block of #: %r"
                             % item.name, self.tok)
        if item.size is None and runs:
            raise self.error("Non-array name contains #: %r" % item.name, tok)

    def decl_pin(self, t):
        """pin DIR TYPE NAME [ARRAY] [= DEFAULT] [if COND] ["doc"];"""
        d = self.expect('name', what='pin direction')
        if d.text not in ('in', 'out', 'io'):
            raise self.error('Invalid pin direction %r' % d.text, d)
        self.item_common('pin', t, d.text)

    def decl_param(self, t):
        """param r|rw TYPE NAME [ARRAY] [= DEFAULT] [if COND] ["doc"];"""
        d = self.expect('name', what='param direction')
        if d.text not in ('r', 'rw'):
            raise self.error('Invalid param direction %r' % d.text, d)
        self.item_common('param', t, d.text)

    def decl_function(self, t):
        """function NAME [fp|nofp] ["doc"];"""
        name = self.expect_cname('function name')
        if self.tok is not None and self.tok.text in ('fp', 'nofp') \
                and self.tok.kind == 'name':
            fp = self.advance()
            line, _ = self.lex.line_col(fp.pos)
            self.comp.warnings.append(
                (line, "Warning: '%s' is no longer supported and will be removed "
                 "in a future version. Remove it from the declaration." % fp.text))
        item = Item('function', name.text, None, None, line=t.pos)
        item.doc = self.opt_string()
        self.end()
        self.comp.add_item(item, self.err_at(name))

    def decl_variable(self, t):
        """variable CTYPE [*]NAME [[N]] [= DEFAULT];"""
        words = [self.expect('name', what='variable type').text]
        stars = ''
        while True:
            while self.peek_is('*'):
                stars += '*'
                self.advance()
            w = self.expect_cname('variable name')
            if self.peek_is('*') or (self.tok is not None and self.tok.kind == 'name'
                                     and not stars and self.tok.text != 'if'):
                words.append(w.text)
                continue
            break
        item = Item('variable', w.text, ' '.join(words) + (' ' + stars if stars else ''),
                    None, line=t.pos)
        if self.peek_is('['):
            self.advance()
            item.size = self.int_token('array size')
            self.expect('punct', ']', "']'")
        item.default = self.parse_default()
        item.doc = self.opt_string()
        self.end()
        self.comp.add_item(item, self.err_at(w))

    def decl_option(self, t):
        """option NAME [VALUE];"""
        name = self.expect('name', what='option name')
        value = 'yes'
        if not self.peek_is(';'):
            v = self.advance()
            value = v.value if v.kind == 'string' else v.text
        self.end()
        if name.text in self.comp.options:
            raise self.error('Duplicate option name %s' % name.text, name)
        self.comp.options[name.text] = value

    def decl_modparam(self, t):
        """modparam int|dummy NAME [= DEFAULT] "doc";"""
        ptype = self.expect('name', what='modparam type').text
        name = self.expect_cname('modparam name')
        item = Item('modparam', name.text, ptype, None, line=t.pos)
        item.default = self.parse_default()
        item.doc = self.opt_string()
        self.end()
        self.comp.add_item(item, self.err_at(name))

    def decl_include(self, t):
        """include <hdr.h>; or include "hdr.h";"""
        if self.tok is not None and self.tok.kind == 'string':
            self.comp.includes.append(('"', self.advance().value))
        else:
            self.expect('punct', '<', "'<' or string")
            self.lex.pos = self.tok.pos
            hdr = self.lex.raw_until('>')
            self.tok = self.lex.next()
            self.expect('punct', '>', "'>'")
            self.comp.includes.append(('<', hdr))
        self.end()

    def doc_decl(self, t):
        """author/description/notes/examples/see_also/license "text";"""
        s = self.tok
        if s is None or s.kind != 'string':
            raise self.error('Expected string after %s' % t.text)
        self.advance()
        self.end()
        self.comp.docs.setdefault(t.text, []).append(s.value)

    decl_author = decl_description = decl_notes = doc_decl
    decl_examples = decl_see_also = decl_license = doc_decl


def parse_comp(path, text, base_name):
    """Parse a .comp text; raise CompError on problems. Returns a Component."""
    decl, code, code_line = split_comp(text)
    comp = Component(path)
    comp.code = code
    comp.code_line = code_line
    comp.code_has_function = 'FUNCTION' in code
    Parser(decl, comp).parse()
    if comp.name != base_name:
        raise CompError('Component name (%s) does not match filename (%s)'
                        % (comp.name, base_name))
    if 'license' not in comp.docs:
        raise CompError('License not specified', 0)
    comp.resolve_includes(os.path.dirname(os.path.abspath(path)))
    return comp
