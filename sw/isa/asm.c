/*
 * asm.c -- the FP3 assembler (syntax in asm.h).
 *
 * One pass over the lines builds the words; `endi LABEL` and `beq ra, rb,
 * LABEL` record a fixup
 * that is resolved at the end, so labels may be used before they are
 * defined.  Register aliases must be defined before they are used.
 * `.include "FILE"` assembles FILE in place (messages name FILE and its
 * line).  Every
 * error is collected with its line and the whole assembly fails if any.
 */
#include "asm.h"
#include "report.h"

#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#define MAX_ERRORS 100
#define MAX_OPERANDS 4

typedef struct {
  char *name;
  int value; /* address (label) or register (alias) */
  int line;
} symbol;

typedef struct {
  symbol *v;
  size_t n, cap;
} symtab;

typedef struct {
  size_t word;
  char *label;
  int line;
  const char *fname; /* the file of `line` (an included one, or the top) */
} fixup;

#define MAX_INCLUDE_DEPTH 8
/* .include directives read in one assembly, all files together.  The
 * nesting limit alone bounds the depth, not the fan-out: a file that
 * includes itself k times would be read k^8 times (hours for k = 10). */
#define MAX_INCLUDES 64

typedef struct {
  const char *fname;
  fp3_image *img;
  symtab labels, aliases;
  fixup *fix;
  size_t nfix, capfix;
  fp3_strbuf err; /* collected messages, one per line */
  int nerr;
  int oom;
  int size_reported;
  size_t count; /* words emitted, may exceed the image (error) */
  int depth;    /* .include nesting */
  int top_line; /* line of the top file's .include being assembled */
  char **names; /* included files' paths, kept for messages to the end */
  size_t nnames;
  unsigned nregs; /* registers r0 .. r(nregs-1) (.regs; default NUM_REGS) */
  int reg_seen;   /* a register was named: .regs may no longer change it */
} asm_state;

static void add_error(asm_state *st, int line, const char *fmt, ...) {
  st->nerr++;
  if (st->nerr > MAX_ERRORS) return;
  char msg[512];
  int k = line > 0 ? snprintf(msg, sizeof msg, "%s:%d: ", st->fname, line)
                   : snprintf(msg, sizeof msg, "%s: ", st->fname);
  if (k < 0) k = 0;
  if ((size_t)k >= sizeof msg) k = (int)sizeof msg - 1;
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg + k, sizeof msg - (size_t)k, fmt, ap);
  va_end(ap);
  if (st->nerr == MAX_ERRORS)
    snprintf(msg + strlen(msg), sizeof msg - strlen(msg),
             "\n%s: too many errors, later ones not shown", st->fname);
  fp3_strbuf_printf(&st->err, "%s\n", msg);
  if (st->err.oom) st->oom = 1;
}

static char *dupstr(const char *s) {
  size_t n = strlen(s) + 1;
  char *p = malloc(n);
  if (p) memcpy(p, s, n);
  return p;
}

static symbol *sym_find(symtab *t, const char *name) {
  for (size_t i = 0; i < t->n; i++)
    if (strcmp(t->v[i].name, name) == 0) return &t->v[i];
  return NULL;
}

static int sym_add(asm_state *st, symtab *t, const char *name, int value,
                   int line) {
  if (t->n == t->cap) {
    size_t cap = t->cap ? t->cap * 2 : 16;
    symbol *p = realloc(t->v, cap * sizeof *p);
    if (!p) {
      st->oom = 1;
      return -1;
    }
    t->v = p;
    t->cap = cap;
  }
  char *copy = dupstr(name);
  if (!copy) {
    st->oom = 1;
    return -1;
  }
  t->v[t->n].name = copy;
  t->v[t->n].value = value;
  t->v[t->n].line = line;
  t->n++;
  return 0;
}

static void sym_free(symtab *t) {
  for (size_t i = 0; i < t->n; i++) free(t->v[i].name);
  free(t->v);
}

static int is_ident_start(int c) { return isalpha(c) || c == '_'; }
static int is_ident_char(int c) { return isalnum(c) || c == '_' || c == '.'; }

static int is_ident(const char *s) {
  if (!is_ident_start((unsigned char)*s)) return 0;
  for (s++; *s; s++)
    if (!is_ident_char((unsigned char)*s)) return 0;
  return 1;
}

/* "r<digits>" or "R<digits>": 1 and the number (may be out of range). */
static int numeric_reg(const char *s, long *num) {
  if ((s[0] != 'r' && s[0] != 'R') || !isdigit((unsigned char)s[1])) return 0;
  for (const char *p = s + 1; *p; p++)
    if (!isdigit((unsigned char)*p)) return 0;
  errno = 0;
  long v = strtol(s + 1, NULL, 10);
  *num = errno ? 1000000L : v;
  return 1;
}

static int parse_reg(asm_state *st, const char *s, int line, unsigned *reg) {
  long num;
  st->reg_seen = 1;
  if (numeric_reg(s, &num)) {
    if (num >= (long)st->nregs) {
      add_error(st, line, "register out of range: %s (registers are r0..r%u)",
                s, st->nregs - 1);
      return -1;
    }
    *reg = (unsigned)num;
    return 0;
  }
  symbol *a = sym_find(&st->aliases, s);
  if (a) {
    *reg = (unsigned)a->value;
    return 0;
  }
  add_error(st, line, "bad register '%s' (expected r0..r%u or a .reg alias)",
            s, st->nregs - 1);
  return -1;
}

/* Does an accepted float literal spell an infinity ("inf", "-Infinity")? */
static int mentions_inf(const char *s) {
  while (*s == '+' || *s == '-') s++;
  return strncasecmp(s, "inf", 3) == 0;
}

int fp3_asm_literal(const char *text, uint32_t *bits, char *why, size_t n) {
  if (text[0] == '0' && (text[1] == 'x' || text[1] == 'X') &&
      strspn(text + 2, "0123456789abcdefABCDEF") == strlen(text + 2) &&
      text[2] != '\0') {
    if (strlen(text + 2) > 8) {
      snprintf(why, n, "bad literal '%s': bit pattern wider than 32 bits",
               text);
      return -1;
    }
    *bits = (uint32_t)strtoul(text + 2, NULL, 16);
    return 0;
  }
  char *end;
  errno = 0;
  float f = strtof(text, &end);
  if (end == text || *end != '\0') {
    snprintf(why, n, "bad literal '%s'", text);
    return -1;
  }
  uint32_t b;
  memcpy(&b, &f, sizeof b);
  if ((b & 0x7fffffffu) == 0x7f800000u && !mentions_inf(text)) {
    snprintf(why, n, "bad literal '%s': out of binary32 range", text);
    return -1;
  }
  *bits = b;
  return 0;
}

/* endi or beq target operand: a label (fixup) or a number.  A beq's
 * target must lie ahead of it. */
static int parse_target(asm_state *st, unsigned opc, const char *s, int line,
                        uint32_t *imm, int *need_fixup) {
  const char *mn = fp3_opc_mnemonic(opc);
  *need_fixup = 0;
  if (isdigit((unsigned char)s[0])) {
    char *end;
    errno = 0;
    unsigned long v = strtoul(s, &end, 0);
    if (*end != '\0' || errno || v > 0xffffffffUL) {
      add_error(st, line, "bad address '%s'", s);
      return -1;
    }
    if (v >= FP3_DEFAULT_IMEM_DEPTH) {
      add_error(st, line, "%s target %lu outside the %d-entry instruction memory",
                mn, v, FP3_DEFAULT_IMEM_DEPTH);
      return -1;
    }
    if (opc == FP3_OP_BEQ && v <= st->count) {
      add_error(st, line, "beq target %lu is not ahead of the beq (at %zu)", v, st->count);
      return -1;
    }
    *imm = (uint32_t)v;
    return 0;
  }
  if (!is_ident(s)) {
    add_error(st, line, "bad label '%s'", s);
    return -1;
  }
  *need_fixup = 1;
  *imm = 0;
  return 0;
}

static void emit(asm_state *st, uint64_t w, int line) {
  if (st->count < FP3_DEFAULT_IMEM_DEPTH) {
    st->img->words[st->count] = w;
    st->img->line[st->count] = st->depth ? st->top_line : line;
  } else if (!st->size_reported) {
    st->size_reported = 1;
    add_error(st, line,
              "program larger than the instruction memory (%d words)",
              FP3_DEFAULT_IMEM_DEPTH);
  }
  st->count++;
}

static void add_fixup(asm_state *st, const char *label, int line) {
  if (st->nfix == st->capfix) {
    size_t cap = st->capfix ? st->capfix * 2 : 16;
    fixup *p = realloc(st->fix, cap * sizeof *p);
    if (!p) {
      st->oom = 1;
      return;
    }
    st->fix = p;
    st->capfix = cap;
  }
  char *copy = dupstr(label);
  if (!copy) {
    st->oom = 1;
    return;
  }
  st->fix[st->nfix].word = st->count;
  st->fix[st->nfix].label = copy;
  st->fix[st->nfix].line = line;
  st->fix[st->nfix].fname = st->fname;
  st->nfix++;
}

static const char *const operand_names[4] = {"rd", "ra", "rb", "imm"};

static void do_insn(asm_state *st, const char *mnem, char **ops, int nops,
                    int line) {
  char lower[16];
  size_t ml = strlen(mnem);
  if (ml >= sizeof lower) ml = sizeof lower - 1;
  for (size_t i = 0; i < ml; i++) lower[i] = (char)tolower((unsigned char)mnem[i]);
  lower[ml] = '\0';
  int opc = strlen(mnem) < sizeof lower ? fp3_opc_lookup(lower) : -1;
  if (opc < 0) {
    add_error(st, line, "unknown mnemonic '%s'", mnem);
    return;
  }
  unsigned uses = (unsigned)fp3_opc_uses((unsigned)opc);
  const unsigned bits[4] = {FP3_USES_RD, FP3_USES_RA, FP3_USES_RB,
                            FP3_USES_IMM};
  int want = 0;
  char form[64] = "";
  for (int i = 0; i < 4; i++)
    if (uses & bits[i]) {
      snprintf(form + strlen(form), sizeof form - strlen(form), "%s%s",
               want ? ", " : "", operand_names[i]);
      want++;
    }
  if (nops != want) {
    add_error(st, line, "wrong operand count: %s takes %d (%s), got %d",
              lower, want, want ? form : "none", nops);
    emit(st, 0, line); /* keep addresses of later labels right */
    return;
  }
  unsigned r[3] = {0, 0, 0};
  uint32_t imm = 0;
  int k = 0, bad = 0, fix = 0;
  for (int i = 0; i < 3; i++)
    if (uses & bits[i])
      if (parse_reg(st, ops[k++], line, &r[i])) bad = 1;
  if (uses & FP3_USES_IMM) {
    const char *text = ops[k];
    if (fp3_opc_has_target((unsigned)opc)) {
      if (parse_target(st, (unsigned)opc, text, line, &imm, &fix)) bad = 1;
    } else {
      char why[160];
      if (fp3_asm_literal(text, &imm, why, sizeof why)) {
        add_error(st, line, "%s", why);
        bad = 1;
      }
    }
  }
  if (fix && !bad) add_fixup(st, ops[k], line);
  emit(st, bad ? 0 : fp3_insn_make((unsigned)opc, r[0], r[1], r[2], imm), line);
}

static void do_binding(asm_state *st, int is_in, char **ops, int nops,
                       int line) {
  const char *dir = is_in ? ".in" : ".out";
  if (nops != 2) {
    add_error(st, line, "wrong operand count: %s takes 2 (NAME, register), got %d",
              dir, nops);
    return;
  }
  char why[200];
  unsigned reg;
  /* a bad name is reported before the register (fp3_image_bind's words) */
  if (!fp3_image_binding_name_ok(is_in, ops[0]) &&
      fp3_image_bind(st->img, is_in, ops[0], 0, line, why, sizeof why)) {
    add_error(st, line, "%s", why);
    return;
  }
  if (parse_reg(st, ops[1], line, &reg)) return;
  if (fp3_image_bind(st->img, is_in, ops[0], (int)reg, line, why, sizeof why))
    add_error(st, line, "%s", why);
}

/* Drop each "DIR/../" of path p in place (DIR not "..", "." or empty):
 * programs/../models/ship.fp3m is models/ship.fp3m.  The same file as long
 * as DIR is a folder, not a link elsewhere, which holds for the paths
 * .model joins. */
static void drop_dotdot(char *p) {
  for (char *q = p; (q = strstr(q, "/../")) != NULL;) {
    char *seg = q;
    while (seg > p && seg[-1] != '/') seg--;
    const size_t len = (size_t)(q - seg);
    if (len == 0 || (len == 2 && seg[0] == '.' && seg[1] == '.') ||
        (len == 1 && seg[0] == '.')) {
      q += 3;
      continue;
    }
    memmove(seg, q + 4, strlen(q + 4) + 1);
    q = seg > p ? seg - 1 : p;
  }
}

/* `.model "FILE"` (beside the program, as .include finds files) and
 * `.integrator NAME`: what the program computes. */
static void do_model(asm_state *st, int is_model, char **ops, int nops, int line) {
  const char *arg = nops == 1 ? ops[0] : "";
  size_t len = strlen(arg);
  if (is_model) {
    if (nops != 1 || len < 3 || arg[0] != '"' || arg[len - 1] != '"') {
      add_error(st, line, ".model takes one file name in double quotes");
      return;
    }
    const char *slash = strrchr(st->fname, '/');
    int dlen = (arg[1] != '/' && slash) ? (int)(slash - st->fname) + 1 : 0;
    if ((size_t)dlen + len - 2 >= sizeof st->img->model) {
      add_error(st, line, ".model: the path is too long");
      return;
    }
    snprintf(st->img->model, sizeof st->img->model, "%.*s%.*s", dlen, st->fname,
             (int)len - 2, arg + 1);
    drop_dotdot(st->img->model);
  } else {
    if (nops != 1 || !is_ident(arg) || len >= sizeof st->img->integrator) {
      add_error(st, line, ".integrator takes one integrator name");
      return;
    }
    memcpy(st->img->integrator, arg, len + 1);
  }
}

static void do_include(asm_state *st, char **ops, int nops, int line);

static void do_directive(asm_state *st, const char *dir, char **ops, int nops,
                         int line) {
  if (strcasecmp(dir, ".reg") == 0) {
    /* `.reg NAME rN` (or `.reg NAME, rN`) */
    char *a = NULL, *b = NULL;
    if (nops == 2) {
      a = ops[0];
      b = ops[1];
    } else if (nops == 1) {
      a = ops[0];
      b = a + strcspn(a, " \t");
      if (*b) {
        *b++ = '\0';
        b += strspn(b, " \t");
      } else {
        b = NULL;
      }
    }
    if (!a || !b || !*b || strpbrk(b, " \t")) {
      add_error(st, line, "wrong operand count: .reg takes NAME and a register");
      return;
    }
    long num;
    if (!is_ident(a) || numeric_reg(a, &num)) {
      add_error(st, line, "bad register alias name '%s'", a);
      return;
    }
    symbol *old = sym_find(&st->aliases, a);
    if (old) {
      add_error(st, line, "duplicate register alias '%s' (line %d)", a,
                old->line);
      return;
    }
    unsigned reg;
    if (parse_reg(st, b, line, &reg)) return;
    sym_add(st, &st->aliases, a, (int)reg, line);
  } else if (strcasecmp(dir, ".regs") == 0) {
    /* `.regs N`: the program is for a build with NUM_REGS >= N */
    char *end;
    long v = nops == 1 ? strtol(ops[0], &end, 10) : 0;
    if (nops != 1 || *end || v < 2 || v > FP3_MAX_REGS)
      add_error(st, line, ".regs takes a register count 2..%d", FP3_MAX_REGS);
    else if (st->reg_seen)
      add_error(st, line, ".regs must come before the first register is named");
    else
      st->nregs = (unsigned)v;
  } else if (strcasecmp(dir, ".in") == 0) {
    do_binding(st, 1, ops, nops, line);
  } else if (strcasecmp(dir, ".out") == 0) {
    do_binding(st, 0, ops, nops, line);
  } else if (strcasecmp(dir, ".model") == 0 || strcasecmp(dir, ".integrator") == 0) {
    do_model(st, strcasecmp(dir, ".model") == 0, ops, nops, line);
  } else if (strcasecmp(dir, ".include") == 0) {
    do_include(st, ops, nops, line);
  } else if (strcasecmp(dir, ".word") == 0) {
    if (nops != 1) {
      add_error(st, line, "wrong operand count: .word takes 1, got %d", nops);
      emit(st, 0, line);
      return;
    }
    const char *t = ops[0];
    size_t nd = strlen(t) > 2 ? strspn(t + 2, "0123456789abcdefABCDEF") : 0;
    if (t[0] != '0' || (t[1] != 'x' && t[1] != 'X') || nd == 0 || nd > 16 ||
        t[2 + nd] != '\0') {
      add_error(st, line, "bad literal '%s': .word takes 0x and 1..16 hex digits",
                t);
      emit(st, 0, line);
      return;
    }
    emit(st, strtoull(t + 2, NULL, 16), line);
  } else {
    add_error(st, line, "unknown directive '%s'", dir);
  }
}

static char *trim(char *s) {
  while (isspace((unsigned char)*s)) s++;
  char *e = s + strlen(s);
  while (e > s && isspace((unsigned char)e[-1])) *--e = '\0';
  return s;
}

static void do_line(asm_state *st, char *text, int line) {
  text[strcspn(text, ";#")] = '\0';
  char *p = trim(text);
  /* labels */
  for (;;) {
    if (!is_ident_start((unsigned char)*p)) break;
    char *q = p;
    while (is_ident_char((unsigned char)*q)) q++;
    char *colon = q;
    while (*colon == ' ' || *colon == '\t') colon++;
    if (*colon != ':') break;
    *q = '\0';
    symbol *old = sym_find(&st->labels, p);
    if (old)
      add_error(st, line, "duplicate label '%s' (first defined at line %d)", p,
                old->line);
    else
      sym_add(st, &st->labels, p, (int)st->count, line);
    p = trim(colon + 1);
  }
  if (*p == '\0') return;
  if (*p == ':') {
    add_error(st, line, "bad label: missing name before ':'");
    return;
  }
  char *word = p;
  char *rest = p + strcspn(p, " \t");
  if (*rest) *rest++ = '\0';
  rest = trim(rest);
  char *ops[MAX_OPERANDS + 1];
  int nops = 0;
  if (*rest) {
    char *s = rest;
    for (;;) {
      char *comma = strchr(s, ',');
      if (comma) *comma = '\0';
      char *op = trim(s);
      if (*op == '\0') {
        add_error(st, line, "empty operand");
        if (word[0] != '.') emit(st, 0, line);
        return;
      }
      if (nops < MAX_OPERANDS + 1) ops[nops] = op;
      nops++;
      if (!comma) break;
      s = comma + 1;
    }
  }
  if (nops > MAX_OPERANDS) {
    add_error(st, line, "wrong operand count: %d operands", nops);
    if (word[0] != '.') emit(st, 0, line);
    return;
  }
  /* an instruction operand may not contain blanks ("add r1 r2, r3") */
  if (strcasecmp(word, ".reg") != 0)
    for (int i = 0; i < nops; i++)
      if (strpbrk(ops[i], " \t")) {
        add_error(st, line, "bad operand '%s' (missing comma?)", ops[i]);
        if (word[0] != '.') emit(st, 0, line);
        return;
      }
  if (word[0] == '.')
    do_directive(st, word, ops, nops, line);
  else
    do_insn(st, word, ops, nops, line);
}

/* The text of file `path` (malloc'd, NUL-terminated), or NULL with
 * "reason" in msg. */
static char *read_text(const char *path, char *msg, size_t n) {
  FILE *f = fopen(path, "r");
  if (!f) {
    snprintf(msg, n, "%s", strerror(errno));
    return NULL;
  }
  size_t cap = 4096, len = 0;
  char *text = malloc(cap);
  int bad = !text;
  while (!bad) {
    if (len + 1 >= cap) {
      char *nt = realloc(text, cap * 2);
      if (!nt) {
        bad = 1;
        break;
      }
      text = nt;
      cap *= 2;
    }
    size_t got = fread(text + len, 1, cap - len - 1, f);
    len += got;
    if (got == 0) break;
  }
  if (!bad && ferror(f)) bad = 2;
  fclose(f);
  if (bad) {
    snprintf(msg, n, "%s", bad == 2 ? "read error" : "out of memory");
    free(text);
    return NULL;
  }
  text[len] = '\0';
  if (memchr(text, '\0', len)) {
    snprintf(msg, n, "not a text file (contains NUL bytes)");
    free(text);
    return NULL;
  }
  return text;
}

/* Assemble every line of src, as file st->fname. */
static void assemble_lines(asm_state *st, const char *src) {
  size_t cap = 256;
  char *buf = malloc(cap);
  int line = 0;
  const char *p = src;
  while (buf && *p) {
    const char *nl = strchr(p, '\n');
    size_t len = nl ? (size_t)(nl - p) : strlen(p);
    if (len + 1 > cap) {
      while (cap < len + 1) cap *= 2;
      char *nb = realloc(buf, cap);
      if (!nb) {
        free(buf);
        buf = NULL;
        break;
      }
      buf = nb;
    }
    memcpy(buf, p, len);
    buf[len] = '\0';
    line++;
    do_line(st, buf, line);
    p = nl ? nl + 1 : p + len;
  }
  if (!buf) st->oom = 1;
  free(buf);
}

/* `.include "FILE"`: assemble FILE here, as if its lines stood in place of
 * the directive.  A relative FILE is found beside the including file. */
static void do_include(asm_state *st, char **ops, int nops, int line) {
  size_t len = nops == 1 ? strlen(ops[0]) : 0;
  if (nops != 1 || len < 3 || ops[0][0] != '"' || ops[0][len - 1] != '"') {
    add_error(st, line, ".include takes one file name in double quotes");
    return;
  }
  if (st->depth >= MAX_INCLUDE_DEPTH) {
    add_error(st, line, ".include nested more than %d deep (does a file include itself?)",
              MAX_INCLUDE_DEPTH);
    return;
  }
  if (st->nnames >= MAX_INCLUDES) {
    add_error(st, line, "more than %d .include directives in one program (does a file include itself?)",
              MAX_INCLUDES);
    return;
  }
  const char *name = ops[0] + 1;
  int nlen = (int)len - 2;
  const char *slash = strrchr(st->fname, '/');
  int dlen = (name[0] != '/' && slash) ? (int)(slash - st->fname) + 1 : 0;
  char **names = realloc(st->names, (st->nnames + 1) * sizeof *names);
  char *path = malloc((size_t)dlen + (size_t)nlen + 1);
  if (names) st->names = names;
  if (!names || !path) {
    free(path);
    st->oom = 1;
    return;
  }
  snprintf(path, (size_t)dlen + (size_t)nlen + 1, "%.*s%.*s", dlen, st->fname, nlen, name);
  st->names[st->nnames++] = path;
  char why[160];
  char *text = read_text(path, why, sizeof why);
  if (!text) {
    add_error(st, line, "cannot include '%s': %s", path, why);
    return;
  }
  const char *outer = st->fname;
  if (st->depth == 0) st->top_line = line;
  st->fname = path;
  st->depth++;
  assemble_lines(st, text);
  st->depth--;
  st->fname = outer;
  free(text);
}

int fp3_asm_string(const char *src, const char *fname, fp3_image *img,
                   char **errors) {
  asm_state st;
  memset(&st, 0, sizeof st);
  st.fname = fname ? fname : "<input>";
  st.img = img;
  st.nregs = FP3_DEFAULT_NUM_REGS;
  fp3_image_init(img);
  if (errors) *errors = NULL;

  assemble_lines(&st, src);

  const char *top = st.fname;
  for (size_t i = 0; i < st.nfix; i++) {
    symbol *l = sym_find(&st.labels, st.fix[i].label);
    st.fname = st.fix[i].fname;
    if (!l)
      add_error(&st, st.fix[i].line, "undefined label '%s'", st.fix[i].label);
    else if (st.fix[i].word < FP3_DEFAULT_IMEM_DEPTH &&
             fp3_insn_opc(img->words[st.fix[i].word]) == FP3_OP_BEQ &&
             (size_t)l->value <= st.fix[i].word)
      add_error(&st, st.fix[i].line, "beq target '%s' (address %d) is not ahead of the beq (at %zu)",
                st.fix[i].label, l->value, st.fix[i].word);
    else if (st.fix[i].word < FP3_DEFAULT_IMEM_DEPTH)
      img->words[st.fix[i].word] |= (uint64_t)(uint32_t)l->value << FP3_IMM_LSB;
    free(st.fix[i].label);
  }
  st.fname = top;
  free(st.fix);
  sym_free(&st.labels);
  sym_free(&st.aliases);
  for (size_t i = 0; i < st.nnames; i++) free(st.names[i]);
  free(st.names);
  img->n = st.count < FP3_DEFAULT_IMEM_DEPTH ? st.count : FP3_DEFAULT_IMEM_DEPTH;

  if (st.oom && st.nerr == 0) st.nerr = 1;
  if (st.nerr == 0) {
    free(st.err.s);
    return 0;
  }
  if (errors) {
    if (st.oom || !st.err.s) {
      *errors = dupstr("out of memory");
    } else {
      *errors = st.err.s;
      st.err.s = NULL;
    }
  }
  free(st.err.s);
  return st.nerr;
}

int fp3_asm_file(const char *path, fp3_image *img, char **errors) {
  if (errors) *errors = NULL;
  fp3_image_init(img);
  char why[160], msg[512];
  char *text = read_text(path, why, sizeof why);
  if (!text) {
    snprintf(msg, sizeof msg, "%s: %s", path, why);
    if (errors) *errors = dupstr(msg);
    return 1;
  }
  int rc = fp3_asm_string(text, path, img, errors);
  free(text);
  return rc;
}
