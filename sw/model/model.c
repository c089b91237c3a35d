/*
 * model.c -- the model language's parser (recursive descent, one line at
 * a time) and its literal golden model in C binary32 (model.h).
 *
 * Compiled with -ffp-contract=off (Makefile): every float expression here
 * is one IEEE operation, so `a + b * c` stays a rounded product and a
 * rounded sum, as the cores compute them.
 */
#include "model.h"

#include <ctype.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fpref.h"

#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "the model's golden model needs float expressions evaluated in float"
#endif

/* ---- the parser ----------------------------------------------------------- */

/* Names that cannot be declared: the step, time, the functions and the
 * line keywords. */
static const char *const reserved[] = {"h", "t", "sqrt", "abs", "min", "max", "exp", "sin",
                                       "cos", "model", "param", "state", "position",
                                       "velocity", "const", "let", "exact"};

/* A function: name, node kind, arguments, 1 if only in `exact` lines. */
static const struct {
  const char *name;
  int kind, args, exact_only;
} funcs[] = {
    {"sqrt", FP3_ME_SQRT, 1, 0}, {"abs", FP3_ME_ABS, 1, 0}, {"min", FP3_ME_MIN, 2, 0},
    {"max", FP3_ME_MAX, 2, 0},   {"exp", FP3_ME_EXP, 1, 1}, {"sin", FP3_ME_SIN, 1, 1},
    {"cos", FP3_ME_COS, 1, 1},
};

typedef struct parser {
  fp3_model *m;
  const char *file;
  const char *line;   /* start of the current line                        */
  const char *p;      /* cursor                                           */
  int lineno;
  int in_exact;       /* parsing an `exact` line: t, exp, sin, cos allowed */
  int cur_let;        /* def index of the let being defined, or -1        */
  char *msg;
  size_t n;
  int failed;
  /* every let of the file, for "defined later" (a pre-scan) */
  char later[FP3_MODEL_MAX_DEFS][FP3_MODEL_NAME_LEN];
  int later_line[FP3_MODEL_MAX_DEFS];
  int nlater;
  int eq_line[FP3_MODEL_MAX_VARS];    /* line of each state's equation     */
  int decl_col[FP3_MODEL_MAX_VARS];   /* column of each state's name        */
} parser;

static int col(const parser *ps, const char *at) { return (int)(at - ps->line) + 1; }

/* Report an error at `at` (the first one sticks). */
static int fail(parser *ps, const char *at, const char *fmt, ...) {
  if (ps->failed) return -1;
  ps->failed = 1;
  int k = snprintf(ps->msg, ps->n, "%s:%d:%d: ", ps->file, ps->lineno, col(ps, at));
  if (k < 0 || (size_t)k >= ps->n) return -1;
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(ps->msg + k, ps->n - (size_t)k, fmt, ap);
  va_end(ap);
  return -1;
}

static int at_eol(const char *p) { return *p == '\0' || *p == '\n' || *p == '#'; }

static void skip_ws(parser *ps) {
  while (*ps->p == ' ' || *ps->p == '\t' || *ps->p == '\r') ps->p++;
}

/* An identifier at the cursor into out; 0, or -1 if there is none. */
static int ident(parser *ps, char out[FP3_MODEL_NAME_LEN]) {
  skip_ws(ps);
  const char *s = ps->p;
  if (!(isalpha((unsigned char)*s) || *s == '_')) {
    if (at_eol(s)) return fail(ps, s, "expected a name, found the end of the line");
    return fail(ps, s, "expected a name, found '%c'", *s);
  }
  while (isalnum((unsigned char)*ps->p) || *ps->p == '_') ps->p++;
  size_t len = (size_t)(ps->p - s);
  if (len >= FP3_MODEL_NAME_LEN)
    return fail(ps, s, "name longer than %d characters", FP3_MODEL_NAME_LEN - 1);
  memcpy(out, s, len);
  out[len] = '\0';
  return 0;
}

static int expect(parser *ps, char c) {
  skip_ws(ps);
  if (*ps->p == c) {
    ps->p++;
    return 0;
  }
  if (at_eol(ps->p)) return fail(ps, ps->p, "expected '%c', found the end of the line", c);
  return fail(ps, ps->p, "expected '%c', found '%c'", c, *ps->p);
}

static int end_of_line(parser *ps) {
  skip_ws(ps);
  if (at_eol(ps->p)) return 0;
  return fail(ps, ps->p, "unexpected '%c' after the end of the line's statement", *ps->p);
}

static int new_node(parser *ps, const char *at, fp3_mexpr x) {
  fp3_model *m = ps->m;
  if (m->nn == FP3_MODEL_MAX_NODES)
    return fail(ps, at, "the model has more than %d expression nodes", FP3_MODEL_MAX_NODES);
  if (x.a >= 0 && m->node[x.a].exact_only) x.exact_only = 1;
  if (x.b >= 0 && m->node[x.b].exact_only) x.exact_only = 1;
  m->node[m->nn] = x;
  return (int)m->nn++;
}

static fp3_mexpr mk(int kind, int a, int b) {
  fp3_mexpr x = {kind, a, b, -1, 0, 0.0, 0};
  return x;
}

static int expr(parser *ps);

/* Where was `name` declared?  "param", "state", "const", "let" or NULL. */
static const char *declared(const parser *ps, const char *name, int *line) {
  const fp3_model *m = ps->m;
  for (unsigned i = 0; i < m->nparam; i++)
    if (strcmp(m->param[i], name) == 0) {
      *line = m->param_line[i];
      return "param";
    }
  for (unsigned i = 0; i < m->nstate; i++)
    if (strcmp(m->state[i], name) == 0) {
      *line = m->state_line[i];
      return "state";
    }
  for (unsigned i = 0; i < m->ndef; i++)
    if (strcmp(m->def[i], name) == 0) {
      *line = 0;
      for (int k = 0; k < ps->nlater; k++)
        if (strcmp(ps->later[k], name) == 0) *line = ps->later_line[k];
      return m->def_is_let[i] ? "let" : "const";
    }
  return NULL;
}

/* A name in an expression: param, state, const, let, or t. */
static int name_ref(parser *ps, const char *at, const char *name) {
  const fp3_model *m = ps->m;
  if (strcmp(name, "t") == 0) {
    if (!ps->in_exact) return fail(ps, at, "'t' (time) is only for `exact` lines");
    fp3_mexpr x = mk(FP3_ME_TIME, -1, -1);
    x.exact_only = 1;
    return new_node(ps, at, x);
  }
  int i = fp3_model_param(m, name);
  if (i >= 0) {
    fp3_mexpr x = mk(FP3_ME_PARAM, -1, -1);
    x.id = i;
    return new_node(ps, at, x);
  }
  i = fp3_model_state(m, name);
  if (i >= 0) {
    fp3_mexpr x = mk(FP3_ME_STATE, -1, -1);
    x.id = i;
    return new_node(ps, at, x);
  }
  for (unsigned d = 0; d < m->ndef; d++)
    if (strcmp(m->def[d], name) == 0) return m->def_node[d];
  if (ps->cur_let >= 0 && strcmp(ps->later[ps->cur_let], name) == 0)
    return fail(ps, at, "let '%s' refers to itself (a cycle)", name);
  for (int k = 0; k < ps->nlater; k++)
    if (strcmp(ps->later[k], name) == 0)
      return fail(ps, at, "'%s' is a let defined later, at line %d: a let is defined "
                          "before use (no cycles)", name, ps->later_line[k]);
  for (size_t f = 0; f < sizeof funcs / sizeof funcs[0]; f++)
    if (strcmp(funcs[f].name, name) == 0)
      return fail(ps, at, "'%s' is a function: write %s(...)", name, name);
  return fail(ps, at, "unknown name '%s'", name);
}

/* 1 if a number starts at p: a digit, or '.' and a digit. */
static int starts_number(const char *p) {
  return isdigit((unsigned char)*p) || (*p == '.' && isdigit((unsigned char)p[1]));
}

/* The number at the cursor (starts_number), decimal or hex float: *f as
 * strtof reads it (RNE, once), *d as strtod does; the cursor moves past
 * it.  0, or -1 for a bad number or one not finite in binary32. */
static int number(parser *ps, float *f, double *d) {
  const char *at = ps->p;
  char *end = NULL;
  const char *q = at;
  while (isalnum((unsigned char)*q) || *q == '.' ||
         ((*q == '+' || *q == '-') &&
          (q[-1] == 'e' || q[-1] == 'E' || q[-1] == 'p' || q[-1] == 'P')))
    q++;
  char buf[128];
  size_t len = (size_t)(q - at);
  if (len >= sizeof buf) return fail(ps, at, "number too long");
  memcpy(buf, at, len);
  buf[len] = '\0';
  *f = strtof(buf, &end);
  if (end != buf + len) return fail(ps, at, "bad number '%s'", buf);
  if (!isfinite(*f)) return fail(ps, at, "number '%s' overflows binary32", buf);
  *d = strtod(buf, NULL);
  ps->p = q;
  return 0;
}

/* A signed number, '-'? NUMBER, as `const` and defaults take it: the
 * minus flips the sign bit (so `-0` is -0).  what: the message when no
 * number follows.  0, or -1. */
static int signed_number(parser *ps, const char *what, float *f, double *d) {
  skip_ws(ps);
  int neg = *ps->p == '-';
  if (neg) ps->p++;
  skip_ws(ps);
  if (!starts_number(ps->p)) return fail(ps, ps->p, "%s", what);
  if (number(ps, f, d)) return -1;
  if (neg) {
    *f = -*f;
    *d = -*d;
  }
  return 0;
}

/* primary := NUMBER | NAME | NAME '(' args ')' | '(' expr ')' */
static int primary(parser *ps) {
  skip_ws(ps);
  const char *at = ps->p;
  if (*at == '(') {
    ps->p++;
    int e = expr(ps);
    if (e < 0 || expect(ps, ')')) return -1;
    return e;
  }
  if (starts_number(at)) {
    float f;
    double d;
    if (number(ps, &f, &d)) return -1;
    fp3_mexpr x = mk(FP3_ME_NUM, -1, -1);
    x.bits = fpref_bits(f);
    x.dval = d;
    return new_node(ps, at, x);
  }
  char name[FP3_MODEL_NAME_LEN];
  if (!(isalpha((unsigned char)*at) || *at == '_')) {
    if (at_eol(at)) return fail(ps, at, "expected an expression, found the end of the line");
    return fail(ps, at, "expected an expression, found '%c'", *at);
  }
  if (ident(ps, name)) return -1;
  skip_ws(ps);
  if (*ps->p != '(') return name_ref(ps, at, name);
  for (size_t f = 0; f < sizeof funcs / sizeof funcs[0]; f++) {
    if (strcmp(funcs[f].name, name) != 0) continue;
    if (funcs[f].exact_only && !ps->in_exact)
      return fail(ps, at, "%s() is only for `exact` lines (the processor has no %s)", name,
                  name);
    ps->p++;
    int a = expr(ps), b = -1;
    if (a < 0) return -1;
    skip_ws(ps);
    if (funcs[f].args == 2) {
      if (*ps->p != ',') return fail(ps, ps->p, "%s takes 2 arguments", name);
      ps->p++;
      if ((b = expr(ps)) < 0) return -1;
      skip_ws(ps);
    }
    if (*ps->p == ',') return fail(ps, ps->p, "%s takes %d argument%s", name, funcs[f].args,
                                   funcs[f].args == 1 ? "" : "s");
    if (expect(ps, ')')) return -1;
    fp3_mexpr x = mk(funcs[f].kind, a, b);
    x.exact_only = funcs[f].exact_only;
    return new_node(ps, at, x);
  }
  return fail(ps, at, "unknown function '%s' (sqrt abs min max)", name);
}

/* unary := '-' unary | primary */
static int unary(parser *ps) {
  skip_ws(ps);
  if (*ps->p == '-') {
    const char *at = ps->p++;
    int a = unary(ps);
    if (a < 0) return -1;
    return new_node(ps, at, mk(FP3_ME_NEG, a, -1));
  }
  return primary(ps);
}

/* term := unary (('*' | '/') unary)*, left-associative */
static int term(parser *ps) {
  int a = unary(ps);
  while (a >= 0) {
    skip_ws(ps);
    char c = *ps->p;
    if (c != '*' && c != '/') break;
    const char *at = ps->p++;
    int b = unary(ps);
    if (b < 0) return -1;
    a = new_node(ps, at, mk(c == '*' ? FP3_ME_MUL : FP3_ME_DIV, a, b));
  }
  return a;
}

/* expr := term (('+' | '-') term)*, left-associative */
static int expr(parser *ps) {
  int a = term(ps);
  while (a >= 0) {
    skip_ws(ps);
    char c = *ps->p;
    if (c != '+' && c != '-') break;
    const char *at = ps->p++;
    int b = term(ps);
    if (b < 0) return -1;
    a = new_node(ps, at, mk(c == '+' ? FP3_ME_ADD : FP3_ME_SUB, a, b));
  }
  return a;
}

/* A new name: not reserved, not declared before. */
static int fresh(parser *ps, const char *at, const char *name) {
  for (size_t i = 0; i < sizeof reserved / sizeof reserved[0]; i++)
    if (strcmp(reserved[i], name) == 0)
      return fail(ps, at, "'%s' is reserved%s", name,
                  strcmp(name, "h") == 0   ? " (the step, a parameter of every model; "
                                             "`param h = NUMBER` gives its default)"
                  : strcmp(name, "t") == 0 ? " (time, in `exact` lines)"
                                           : "");
  int line;
  const char *what = declared(ps, name, &line);
  if (what) return fail(ps, at, "'%s' is declared twice (a %s, line %d)", name, what, line);
  return 0;
}

/* `= NUMBER` after the name at `at` on a declaration line, if there is
 * one: *has 1 and the number in *f, *d; else *has 0.  A second `=` is a
 * default given twice.  0, or -1. */
static int default_value(parser *ps, const char *at, const char *name, unsigned char *has,
                         float *f, double *d) {
  skip_ws(ps);
  *has = 0;
  if (*ps->p != '=') return 0;
  ps->p++;
  if (signed_number(ps, "a default is a signed number, finite in binary32 (NAME = NUMBER)",
                    f, d))
    return -1;
  skip_ws(ps);
  if (*ps->p == '=') return fail(ps, at, "'%s' is given a default twice", name);
  *has = 1;
  return 0;
}

/* param / state / position / velocity: a comma-separated list of names,
 * each with an optional default `= NUMBER`.  h, the step (param 0 of
 * every model), may be named once on a param line, with a default > 0. */
static int name_list(parser *ps, int is_param, int role) {
  fp3_model *m = ps->m;
  for (;;) {
    skip_ws(ps);
    const char *at = ps->p;
    char name[FP3_MODEL_NAME_LEN];
    if (ident(ps, name)) return -1;
    skip_ws(ps);
    if (is_param && strcmp(name, "h") == 0 && *ps->p == '=') {
      if (m->param_has_def[0])
        return fail(ps, at, "'h' is given a default twice (the first at line %d)",
                    m->param_def_line[0]);
      const char *num = ps->p + 1;
      while (*num == ' ' || *num == '\t' || *num == '\r') num++;
      if (default_value(ps, at, name, &m->param_has_def[0], &m->param_def[0],
                        &m->param_def_d[0]))
        return -1;
      if (!(m->param_def[0] > 0.0f))
        return fail(ps, num, "the step h must be above 0 (its default is %.9g)",
                    (double)m->param_def[0]);
      m->param_def_line[0] = ps->lineno;
    } else if (fresh(ps, at, name)) {
      return -1;
    } else if (is_param) {
      if (m->nparam == FP3_MODEL_MAX_VARS)
        return fail(ps, at, "more than %d params (h included)", FP3_MODEL_MAX_VARS);
      unsigned k = m->nparam;
      snprintf(m->param[k], FP3_MODEL_NAME_LEN, "%s", name);
      m->param_line[k] = ps->lineno;
      if (default_value(ps, at, name, &m->param_has_def[k], &m->param_def[k],
                        &m->param_def_d[k]))
        return -1;
      if (m->param_has_def[k]) m->param_def_line[k] = ps->lineno;
      m->nparam++;
    } else {
      if (m->nstate == FP3_MODEL_MAX_VARS)
        return fail(ps, at, "more than %d state variables", FP3_MODEL_MAX_VARS);
      unsigned k = m->nstate;
      snprintf(m->state[k], FP3_MODEL_NAME_LEN, "%s", name);
      m->state_line[k] = ps->lineno;
      m->role[k] = role;
      m->deriv[k] = -1;
      m->exact[k] = -1;
      ps->decl_col[k] = col(ps, at);
      if (default_value(ps, at, name, &m->state_has_def[k], &m->state_def[k],
                        &m->state_def_d[k]))
        return -1;
      m->nstate++;
    }
    skip_ws(ps);
    if (*ps->p != ',') return end_of_line(ps);
    ps->p++;
  }
}

/* const NAME = NUMBER (a signed number; its node is the named constant). */
static int def_line(parser *ps, int is_let) {
  fp3_model *m = ps->m;
  skip_ws(ps);
  const char *at = ps->p;
  char name[FP3_MODEL_NAME_LEN];
  if (ident(ps, name) || fresh(ps, at, name) || expect(ps, '=')) return -1;
  if (m->ndef == FP3_MODEL_MAX_DEFS)
    return fail(ps, at, "more than %d consts and lets", FP3_MODEL_MAX_DEFS);
  int e;
  if (is_let) {
    ps->cur_let = -1;
    for (int k = 0; k < ps->nlater; k++)
      if (ps->later_line[k] == ps->lineno && strcmp(ps->later[k], name) == 0) ps->cur_let = k;
    e = expr(ps);
    ps->cur_let = -1;
  } else {
    skip_ws(ps);
    const char *num = ps->p;
    float f;
    double d;
    e = -1;
    if (!signed_number(ps, "a const is a number (write `let` for an expression)", &f, &d)) {
      fp3_mexpr x = mk(FP3_ME_NUM, -1, -1);
      x.bits = fpref_bits(f);
      x.dval = d;
      e = new_node(ps, num, x);
    }
  }
  if (e < 0 || end_of_line(ps)) return -1;
  snprintf(m->def[m->ndef], FP3_MODEL_NAME_LEN, "%s", name);
  m->def_node[m->ndef] = e;
  m->def_is_let[m->ndef++] = is_let;
  return 0;
}

/* NAME' = EXPR, or exact NAME = EXPR. */
static int equation(parser *ps, const char *at, const char *name, int is_exact) {
  fp3_model *m = ps->m;
  int i = fp3_model_state(m, name);
  if (i < 0) {
    int line;
    const char *what = declared(ps, name, &line);
    if (what) return fail(ps, at, "'%s' is a %s, not a state variable", name, what);
    return fail(ps, at, "'%s' is not a state variable (declare it on a `state` line first)",
                name);
  }
  if (!is_exact) {
    if (m->deriv[i] >= 0)
      return fail(ps, at, "state '%s' has two equations (the first at line %d)", name,
                  ps->eq_line[i]);
  } else if (m->exact[i] >= 0) {
    return fail(ps, at, "state '%s' has two `exact` lines", name);
  }
  if (expect(ps, '=')) return -1;
  ps->in_exact = is_exact;
  int e = expr(ps);
  ps->in_exact = 0;
  if (e < 0 || end_of_line(ps)) return -1;
  if (is_exact) {
    m->exact[i] = e;
  } else {
    m->deriv[i] = e;
    ps->eq_line[i] = ps->lineno;
  }
  return 0;
}

/* The names of every let with their lines, before parsing (for "defined
 * later"). */
static void prescan(parser *ps, const char *src) {
  int line = 1;
  for (const char *p = src; *p; line++) {
    while (*p == ' ' || *p == '\t') p++;
    if (strncmp(p, "let", 3) == 0 && (p[3] == ' ' || p[3] == '\t') &&
        ps->nlater < FP3_MODEL_MAX_DEFS) {
      p += 3;
      while (*p == ' ' || *p == '\t') p++;
      size_t len = 0;
      while ((isalnum((unsigned char)p[len]) || p[len] == '_') && len < FP3_MODEL_NAME_LEN - 1)
        len++;
      memcpy(ps->later[ps->nlater], p, len);
      ps->later[ps->nlater][len] = '\0';
      ps->later_line[ps->nlater++] = line;
    }
    p = strchr(p, '\n');
    if (!p) break;
    p++;
  }
}

static int statement(parser *ps, int *seen_stmt) {
  fp3_model *m = ps->m;
  skip_ws(ps);
  if (at_eol(ps->p)) return 0;
  const char *at = ps->p;
  char word[FP3_MODEL_NAME_LEN];
  if (ident(ps, word)) return -1;
  int first = !*seen_stmt;
  *seen_stmt = 1;
  if (strcmp(word, "model") == 0) {
    if (!first) return fail(ps, at, "`model NAME` must be the first statement");
    return ident(ps, m->name) || end_of_line(ps);
  }
  if (strcmp(word, "param") == 0) return name_list(ps, 1, 0);
  if (strcmp(word, "state") == 0) return name_list(ps, 0, FP3_MR_STATE);
  if (strcmp(word, "position") == 0) return name_list(ps, 0, FP3_MR_POSITION);
  if (strcmp(word, "velocity") == 0) return name_list(ps, 0, FP3_MR_VELOCITY);
  if (strcmp(word, "const") == 0) return def_line(ps, 0);
  if (strcmp(word, "let") == 0) return def_line(ps, 1);
  if (strcmp(word, "exact") == 0) {
    skip_ws(ps);
    const char *nat = ps->p;
    char name[FP3_MODEL_NAME_LEN];
    if (ident(ps, name)) return -1;
    return equation(ps, nat, name, 1);
  }
  skip_ws(ps);
  if (*ps->p != '\'')
    return fail(ps, ps->p, "expected NAME' = EXPR or a keyword (model param state position "
                           "velocity const let exact), found '%s'", word);
  ps->p++;
  return equation(ps, at, word, 0);
}

int fp3_model_parse(const char *src, const char *file, fp3_model *m, char *msg, size_t n) {
  memset(m, 0, sizeof *m);
  snprintf(m->file, sizeof m->file, "%s", file);
  snprintf(m->param[0], FP3_MODEL_NAME_LEN, "h");
  m->nparam = 1;
  parser *ps = calloc(1, sizeof *ps);
  if (!ps) {
    snprintf(msg, n, "%s: out of memory", file);
    return -1;
  }
  ps->m = m;
  ps->file = file;
  ps->msg = msg;
  ps->n = n;
  ps->cur_let = -1;
  prescan(ps, src);
  int seen = 0, rc = 0;
  const char *line = src;
  for (ps->lineno = 1; line && *line && rc == 0; ps->lineno++) {
    ps->line = ps->p = line;
    rc = statement(ps, &seen);
    line = strchr(line, '\n');
    if (line) line++;
  }
  if (rc == 0 && m->nstate == 0) {
    snprintf(msg, n, "%s:%d:1: the model declares no state (a `state` line)", file,
             ps->lineno > 1 ? ps->lineno - 1 : 1);
    rc = -1;
  }
  for (unsigned i = 0; rc == 0 && i < m->nstate; i++)
    if (m->deriv[i] < 0) {
      snprintf(msg, n, "%s:%d:%d: state '%s' has no equation (%s' = ...)", file,
               m->state_line[i], ps->decl_col[i], m->state[i], m->state[i]);
      rc = -1;
    }
  if (rc == 0) {
    int pos = 0, vel = 0, plain = 0;
    for (unsigned i = 0; i < m->nstate; i++) {
      pos += m->role[i] == FP3_MR_POSITION;
      vel += m->role[i] == FP3_MR_VELOCITY;
      plain += m->role[i] == FP3_MR_STATE;
    }
    if ((pos || vel) && (!pos || !vel || plain)) {
      snprintf(msg, n, "%s:%d:1: a split state needs `position` and `velocity` lines and "
               "no `state` line (%d positions, %d velocities, %d plain)", file,
               m->state_line[0], pos, vel, plain);
      rc = -1;
    }
  }
  if (rc == 0 && !m->name[0]) { /* the file's base name without .fp3m */
    const char *b = strrchr(file, '/');
    b = b ? b + 1 : file;
    size_t len = strcspn(b, ".");
    if (len >= FP3_MODEL_NAME_LEN) len = FP3_MODEL_NAME_LEN - 1;
    memcpy(m->name, b, len);
    m->name[len] = '\0';
  }
  free(ps);
  return rc;
}

int fp3_model_load(const char *path, fp3_model *m, char *msg, size_t n) {
  FILE *f = fopen(path, "rb");
  if (!f) {
    snprintf(msg, n, "%s: cannot read the model file", path);
    return -1;
  }
  size_t cap = 4096, len = 0;
  char *buf = malloc(cap);
  for (size_t got; buf && (got = fread(buf + len, 1, cap - len - 1, f)) > 0;) {
    len += got;
    if (len + 1 == cap) {
      char *nb = realloc(buf, cap *= 2);
      if (!nb) free(buf);
      buf = nb;
    }
  }
  int bad = ferror(f);
  fclose(f);
  if (!buf || bad) {
    free(buf);
    snprintf(msg, n, "%s: cannot read the model file", path);
    return -1;
  }
  buf[len] = '\0';
  if (strlen(buf) != len) {
    free(buf);
    snprintf(msg, n, "%s: a NUL byte in the model file", path);
    return -1;
  }
  int rc = fp3_model_parse(buf, path, m, msg, n);
  free(buf);
  return rc;
}

int fp3_model_param(const fp3_model *m, const char *name) {
  for (unsigned i = 0; i < m->nparam; i++)
    if (strcmp(m->param[i], name) == 0) return (int)i;
  return -1;
}

int fp3_model_state(const fp3_model *m, const char *name) {
  for (unsigned i = 0; i < m->nstate; i++)
    if (strcmp(m->state[i], name) == 0) return (int)i;
  return -1;
}

/* Mark the nodes an expression reads. */
static void mark(const fp3_model *m, int i, unsigned char *seen) {
  if (i < 0 || seen[i]) return;
  seen[i] = 1;
  mark(m, m->node[i].a, seen);
  mark(m, m->node[i].b, seen);
}

int fp3_model_uses(const fp3_model *m, int kind) {
  unsigned char seen[FP3_MODEL_MAX_NODES] = {0};
  for (unsigned i = 0; i < m->nstate; i++) mark(m, m->deriv[i], seen);
  for (unsigned i = 0; i < m->nn; i++)
    if (seen[i] && m->node[i].kind == kind) return 1;
  return 0;
}

int fp3_model_split(const fp3_model *m) {
  return m->nstate > 0 && m->role[0] != FP3_MR_STATE;
}

int fp3_model_verlet_ok(const fp3_model *m, unsigned *vel, unsigned *reads) {
  if (!fp3_model_split(m)) return 0;
  for (unsigned i = 0; i < m->nstate; i++) {
    if (m->role[i] != FP3_MR_VELOCITY) continue;
    unsigned char seen[FP3_MODEL_MAX_NODES] = {0};
    mark(m, m->deriv[i], seen);
    for (unsigned k = 0; k < m->nn; k++)
      if (seen[k] && m->node[k].kind == FP3_ME_STATE &&
          m->role[m->node[k].id] == FP3_MR_VELOCITY) {
        if (vel) *vel = i;
        if (reads) *reads = (unsigned)m->node[k].id;
        return 0;
      }
  }
  return 1;
}

const char *fp3_mexpr_op_name(int kind) {
  static const char *const names[FP3_ME_KINDS] = {
      "number", "param", "state", "t", "+", "-", "*", "/", "unary -",
      "sqrt", "abs", "min", "max", "exp", "sin", "cos"};
  return kind >= 0 && kind < FP3_ME_KINDS ? names[kind] : "?";
}

/* ---- binary32 evaluation -------------------------------------------------- */

/* min and max: IEEE 754-2019 §9.6 minimum and maximum, the definition of
 * the processor's min and max (docs/fp-cores.md): a NaN operand gives a
 * NaN (a quieted if a is a NaN, else b quieted, as the arithmetic), -0 is
 * below +0, otherwise the smaller / larger operand exactly.  The one place
 * the language's min and max are defined in binary32. */
static uint32_t order_key(uint32_t x) { return (x & 0x80000000u) ? ~x : x | 0x80000000u; }

float fp3_model_minmax32(float a, float b, int want_max) {
  uint32_t x = fpref_bits(a), y = fpref_bits(b);
  if (fpref_is_nan(x) || fpref_is_nan(y)) return fpref_float((fpref_is_nan(x) ? x : y) | 0x00400000u);
  int a_below = order_key(x) < order_key(y);
  return (a_below != want_max) ? a : b;
}

/* Value of node x in binary32 from its operands' values p, q. */
static float op32(const fp3_mexpr *x, float p, float q) {
  switch (x->kind) {
  case FP3_ME_ADD: return p + q;
  case FP3_ME_SUB: return p - q;
  case FP3_ME_MUL: return p * q;
  case FP3_ME_DIV: return p / q;
  case FP3_ME_NEG: return fpref_float(fpref_bits(p) ^ 0x80000000u);
  case FP3_ME_SQRT: return sqrtf(p);
  case FP3_ME_ABS: return fpref_float(fpref_bits(p) & 0x7FFFFFFFu);
  case FP3_ME_MIN: return fp3_model_minmax32(p, q, 0);
  case FP3_ME_MAX: return fp3_model_minmax32(p, q, 1);
  default: return NAN;
  }
}

void fp3_model_eval_f(const fp3_model *m, const float *in, const float *y, float *f,
                      float *val) {
  for (unsigned i = 0; i < m->nn; i++) {
    const fp3_mexpr *x = &m->node[i];
    if (x->exact_only) continue;
    switch (x->kind) {
    case FP3_ME_NUM: val[i] = fpref_float(x->bits); break;
    case FP3_ME_PARAM: val[i] = in[x->id]; break;
    case FP3_ME_STATE: val[i] = y[x->id]; break;
    default: val[i] = op32(x, val[x->a], x->b >= 0 ? val[x->b] : 0.0f); break;
    }
  }
  for (unsigned i = 0; i < m->nstate; i++) f[i] = val[m->deriv[i]];
}

/* The table of integrators: name, carried values per state variable (2:
 * a compensation or an acceleration beside it), the shape it needs. */
enum { NEED_NONE, NEED_SPLIT, NEED_VERLET, NEED_PAIRED };
static const struct {
  const char *name;
  unsigned carried;
  int need;
} integ_table[] = {
    {"euler", 1, NEED_NONE},      {"rk2", 1, NEED_NONE},        {"rk4", 1, NEED_NONE},
    {"rk4comp", 2, NEED_NONE},    {"symeuler", 1, NEED_SPLIT},  {"verlet", 1, NEED_VERLET},
    {"rk4se", 1, NEED_SPLIT},     {"rk4secomp", 2, NEED_SPLIT}, {"rk4vs", 1, NEED_SPLIT},
    {"rk4vscomp", 2, NEED_SPLIT}, {"verletp", 2, NEED_PAIRED},
};
#define INTEG_COUNT (sizeof integ_table / sizeof integ_table[0])

static int integ_index(const char *name) {
  for (unsigned i = 0; i < INTEG_COUNT; i++)
    if (strcmp(integ_table[i].name, name) == 0) return (int)i;
  return -1;
}

const char *fp3_model_integrators(void) {
  return "euler rk2 rk4 rk4comp symeuler verlet rk4se rk4secomp rk4vs rk4vscomp verletp";
}

int fp3_model_integrator_known(const char *name) { return integ_index(name) >= 0; }

unsigned fp3_model_carried(const fp3_model *m, const char *integ) {
  int k = integ_index(integ);
  return m->nstate * (k >= 0 ? integ_table[k].carried : 1u);
}

int fp3_model_pair(const fp3_model *m, unsigned pos) {
  if (pos >= m->nstate || m->role[pos] != FP3_MR_POSITION) return -1;
  const fp3_mexpr *x = &m->node[m->deriv[pos]];
  if (x->kind != FP3_ME_STATE || m->role[x->id] != FP3_MR_VELOCITY) return -1;
  return x->id;
}

int fp3_model_integrator_applies(const fp3_model *m, const char *integ) {
  int k = integ_index(integ);
  if (k < 0) return 0;
  switch (integ_table[k].need) {
  case NEED_SPLIT: return fp3_model_split(m);
  case NEED_VERLET: return fp3_model_verlet_ok(m, NULL, NULL);
  case NEED_PAIRED:
    if (!fp3_model_split(m)) return 0;
    for (unsigned i = 0; i < m->nstate; i++)
      if (m->role[i] == FP3_MR_POSITION && fp3_model_pair(m, i) < 0) return 0;
    return 1;
  default: return 1;
  }
}

void fp3_model_start_literal(const fp3_model *m, const char *integ, const float *in,
                             float *y) {
  const unsigned ns = m->nstate, carried = fp3_model_carried(m, integ);
  for (unsigned i = ns; i < carried; i++) y[i] = 0.0f;
  if (strcmp(integ, "verletp") == 0) { /* the acceleration at the start */
    float val[FP3_MODEL_MAX_NODES], f[FP3_MODEL_MAX_VARS];
    fp3_model_eval_f(m, in, y, f, val);
    for (unsigned i = 0; i < ns; i++)
      if (m->role[i] == FP3_MR_VELOCITY) y[ns + i] = f[i];
  }
}

/* y += d, Kahan-compensated (Kahan 1965): *c, carried from one
 * integration to the next, holds -(what the rounding has lost so far). */
static void kahan_add(float *y, float *c, float d) {
  const float yk = d - *c;
  const float t = *y + yk;
  const float z = t - *y;
  *c = z - yk;
  *y = t;
}

/* The RK4 family (model.h): rk4 and rk4comp take every state variable in
 * the k form (all); rk4vs, rk4vscomp the velocities in it and each
 * position by (h sixth) (f1 + 2 (f2 + f3) + f4); rk4se, rk4secomp (se) the
 * velocities with the positions held, then the positions by the new
 * velocities.  comp: every update Kahan-compensated. */
static void step_rk4(const fp3_model *m, int all, int se, int comp, const float *in, float *y) {
  const unsigned ns = m->nstate;
  const float h = in[0];
  float val[FP3_MODEL_MAX_NODES];
  float f[4][FP3_MODEL_MAX_VARS], t[FP3_MODEL_MAX_VARS], k[3][FP3_MODEL_MAX_VARS];
  fp3_model_eval_f(m, in, y, f[0], val);
  for (unsigned s = 0; s < 3; s++) {
    for (unsigned j = 0; j < ns; j++) k[s][j] = h * f[s][j];
    for (unsigned j = 0; j < ns; j++)
      t[j] = se && m->role[j] == FP3_MR_POSITION ? y[j]
             : s < 2                             ? y[j] + 0.5f * k[s][j]
                                                 : y[j] + k[s][j];
    fp3_model_eval_f(m, in, t, f[s + 1], val);
  }
  for (unsigned i = 0; i < ns; i++) {
    float d;
    if (all || m->role[i] == FP3_MR_VELOCITY) {
      const float k4 = h * f[3][i];
      d = FP3_RK4_SIXTH * (((k[0][i] + 2.0f * k[1][i]) + 2.0f * k[2][i]) + k4);
    } else if (!se) { /* the s-stages of RK4 on x' = f: h/6 (f1 + 2 (f2 + f3) + f4) */
      const float h6 = h * FP3_RK4_SIXTH;
      d = h6 * ((f[0][i] + 2.0f * (f[1][i] + f[2][i])) + f[3][i]);
    } else {
      continue;
    }
    if (comp) kahan_add(&y[i], &y[ns + i], d);
    else y[i] = y[i] + d;
  }
  if (!se) return;
  fp3_model_eval_f(m, in, y, f[0], val); /* positions by the new velocities */
  for (unsigned i = 0; i < ns; i++)
    if (m->role[i] == FP3_MR_POSITION) {
      const float d = h * f[0][i];
      if (comp) kahan_add(&y[i], &y[ns + i], d);
      else y[i] = y[i] + d;
    }
}

/* verletp (model.h): positions by h u + h^2/2 a, an Euler-predicted
 * velocity, the trapezoid of the accelerations, a carried. */
static void step_verletp(const fp3_model *m, const float *in, float *y) {
  const unsigned ns = m->nstate;
  const float h = in[0], hh = 0.5f * h, hh2 = 0.5f * (h * h);
  float val[FP3_MODEL_MAX_NODES], f[FP3_MODEL_MAX_VARS], t[FP3_MODEL_MAX_VARS] = {0};
  const float *a = y + ns;
  for (unsigned i = 0; i < ns; i++) {
    if (m->role[i] == FP3_MR_POSITION) {
      const unsigned p = (unsigned)fp3_model_pair(m, i);
      t[i] = y[i] + ((h * y[p]) + (hh2 * a[p]));
    } else {
      t[i] = y[i] + h * a[i];
    }
  }
  fp3_model_eval_f(m, in, t, f, val); /* at the new positions, predicted velocities */
  for (unsigned i = 0; i < ns; i++)
    y[i] = m->role[i] == FP3_MR_POSITION ? t[i] : y[i] + hh * (a[i] + f[i]);
  fp3_model_eval_f(m, in, y, f, val); /* the next integration's acceleration */
  for (unsigned i = 0; i < ns; i++)
    if (m->role[i] == FP3_MR_VELOCITY) y[ns + i] = f[i];
}

int fp3_model_step_literal(const fp3_model *m, const char *integ, const float *in,
                           float *y) {
  const unsigned ns = m->nstate;
  const float h = in[0];
  float val[FP3_MODEL_MAX_NODES];
  float f[FP3_MODEL_MAX_VARS] = {0}, t[FP3_MODEL_MAX_VARS] = {0};
  if (strcmp(integ, "euler") == 0) {
    fp3_model_eval_f(m, in, y, f, val);
    for (unsigned i = 0; i < ns; i++) y[i] = y[i] + h * f[i];
  } else if (strcmp(integ, "rk2") == 0) {
    const float hh = 0.5f * h;
    fp3_model_eval_f(m, in, y, f, val);
    for (unsigned j = 0; j < ns; j++) t[j] = y[j] + hh * f[j];
    fp3_model_eval_f(m, in, t, f, val);
    for (unsigned i = 0; i < ns; i++) y[i] = y[i] + h * f[i];
  } else if (strcmp(integ, "rk4") == 0 || strcmp(integ, "rk4comp") == 0) {
    step_rk4(m, 1, 0, strcmp(integ, "rk4comp") == 0, in, y);
  } else if (strcmp(integ, "symeuler") == 0 && fp3_model_split(m)) {
    fp3_model_eval_f(m, in, y, f, val);
    for (unsigned i = 0; i < ns; i++)
      if (m->role[i] == FP3_MR_VELOCITY) y[i] = y[i] + h * f[i];
    fp3_model_eval_f(m, in, y, f, val);
    for (unsigned i = 0; i < ns; i++)
      if (m->role[i] == FP3_MR_POSITION) y[i] = y[i] + h * f[i];
  } else if (strncmp(integ, "rk4se", 5) == 0 || strncmp(integ, "rk4vs", 5) == 0) {
    if (!fp3_model_integrator_applies(m, integ)) return -1;
    step_rk4(m, 0, strncmp(integ, "rk4se", 5) == 0, strstr(integ, "comp") != NULL, in, y);
  } else if (strcmp(integ, "verletp") == 0) {
    if (!fp3_model_integrator_applies(m, integ)) return -1;
    step_verletp(m, in, y);
  } else if (strcmp(integ, "verlet") == 0 && fp3_model_verlet_ok(m, NULL, NULL)) {
    const float hh = 0.5f * h;
    fp3_model_eval_f(m, in, y, f, val); /* kick: half a step of velocity */
    for (unsigned i = 0; i < ns; i++)
      if (m->role[i] == FP3_MR_VELOCITY) y[i] = y[i] + hh * f[i];
    fp3_model_eval_f(m, in, y, f, val); /* drift: positions with those velocities */
    for (unsigned i = 0; i < ns; i++)
      if (m->role[i] == FP3_MR_POSITION) y[i] = y[i] + h * f[i];
    fp3_model_eval_f(m, in, y, f, val); /* kick at the new positions */
    for (unsigned i = 0; i < ns; i++)
      if (m->role[i] == FP3_MR_VELOCITY) y[i] = y[i] + hh * f[i];
  } else {
    return -1;
  }
  return 0;
}

/* ---- double ------------------------------------------------------------------- */

/* Nodes 0..last in double; STATE reads y, TIME t. */
static void eval_double(const fp3_model *m, unsigned last, const double *in, const double *y,
                        double t, int with_exact, double *val) {
  for (unsigned i = 0; i <= last && i < m->nn; i++) {
    const fp3_mexpr *x = &m->node[i];
    if (x->exact_only && !with_exact) continue;
    const double p = x->a >= 0 ? val[x->a] : 0.0, q = x->b >= 0 ? val[x->b] : 0.0;
    double r;
    switch (x->kind) {
    case FP3_ME_NUM: r = x->dval; break;
    case FP3_ME_PARAM: r = in[x->id]; break;
    case FP3_ME_STATE: r = y[x->id]; break;
    case FP3_ME_TIME: r = t; break;
    case FP3_ME_ADD: r = p + q; break;
    case FP3_ME_SUB: r = p - q; break;
    case FP3_ME_MUL: r = p * q; break;
    case FP3_ME_DIV: r = p / q; break;
    case FP3_ME_NEG: r = -p; break;
    case FP3_ME_SQRT: r = sqrt(p); break;
    case FP3_ME_ABS: r = fabs(p); break;
    case FP3_ME_MIN: r = fmin(p, q); break;
    case FP3_ME_MAX: r = fmax(p, q); break;
    case FP3_ME_EXP: r = exp(p); break;
    case FP3_ME_SIN: r = sin(p); break;
    case FP3_ME_COS: r = cos(p); break;
    default: r = NAN; break;
    }
    val[i] = r;
  }
}

void fp3_model_eval_f_double(const fp3_model *m, const double *in, const double *y,
                             double *f, double *val) {
  if (m->nn) eval_double(m, m->nn - 1, in, y, 0.0, 0, val);
  for (unsigned i = 0; i < m->nstate; i++) f[i] = val[m->deriv[i]];
}

int fp3_model_exact(const fp3_model *m, unsigned i, const double *in, const double *y0,
                    double t, double *out) {
  if (i >= m->nstate || m->exact[i] < 0) return -1;
  double *val = malloc(m->nn * sizeof *val);
  if (!val) return -1;
  eval_double(m, (unsigned)m->exact[i], in, y0, t, 1, val);
  *out = val[m->exact[i]];
  free(val);
  return 0;
}
