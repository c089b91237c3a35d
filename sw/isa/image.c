/*
 * image.c -- program image: ISA checks of instruction words and the .hex
 * image file (see image.h for the format).
 */
#include "image.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void fp3_image_init(fp3_image *img) { memset(img, 0, sizeof *img); }

int fp3_image_binding_name_ok(int is_in, const char *name) {
  const char *id = is_in && name[0] == '-' ? name + 1 : name;
  int ok = isalpha((unsigned char)id[0]) || id[0] == '_';
  for (const char *q = id; ok && *q; q++) ok = isalnum((unsigned char)*q) || *q == '_';
  return ok;
}

int fp3_image_bind(fp3_image *img, int is_in, const char *name, int reg, int line,
                   char *why, size_t n) {
  const char *dir = is_in ? ".in" : ".out";
  if (!fp3_image_binding_name_ok(is_in, name)) {
    snprintf(why, n, "bad %s name '%s': a model's param, state variable (NAME0: its initial "
             "value) or parameter-only let%s", dir, name,
             is_in ? ", '-' before it for the negated value" : "");
    return -1;
  }
  fp3_binding *list = is_in ? img->bind_in : img->bind_out;
  unsigned *count = is_in ? &img->nbind_in : &img->nbind_out;
  if (strlen(name) >= FP3_BIND_NAME_LEN) {
    snprintf(why, n, "%s name '%s' longer than %d characters", dir, name, FP3_BIND_NAME_LEN - 1);
    return -1;
  }
  for (unsigned i = 0; i < *count; i++) {
    if (strcmp(list[i].name, name) == 0) {
      snprintf(why, n, "duplicate %s %s", dir, name);
      return -1;
    }
    if (list[i].reg == reg) {
      snprintf(why, n, "r%d is already bound by %s %s", reg, dir, list[i].name);
      return -1;
    }
  }
  if (*count == FP3_MAX_BINDINGS) {
    snprintf(why, n, "more than %d %s bindings", FP3_MAX_BINDINGS, dir);
    return -1;
  }
  fp3_binding *b = &list[(*count)++];
  snprintf(b->name, sizeof b->name, "%s", name);
  b->reg = reg;
  b->line = line;
  return 0;
}

uint64_t fp3_insn_make(unsigned opc, unsigned rd, unsigned ra, unsigned rb,
                       uint32_t imm) {
  const uint64_t rmask = (1u << FP3_REG_WIDTH) - 1u;
  const uint64_t omask = (1u << FP3_OPC_WIDTH) - 1u;
  return ((opc & omask) << FP3_OPC_LSB) | ((rd & rmask) << FP3_RD_LSB) |
         ((ra & rmask) << FP3_RA_LSB) | ((rb & rmask) << FP3_RB_LSB) |
         ((uint64_t)imm << FP3_IMM_LSB);
}

int fp3_opc_uses(unsigned opc) {
  switch (opc) {
#define X(name, code, mnem, uses, unit, desc) \
  case code:                                  \
    return (uses);
    FP3_OPCODES(X)
#undef X
  default:
    return -1;
  }
}

unsigned fp3_opc_unit(unsigned opc) {
  switch (opc) {
#define X(name, code, mnem, uses, unit, desc) \
  case code:                                  \
    return (unit);
    FP3_OPCODES(X)
#undef X
  default:
    return FP3_UNIT_NONE;
  }
}

const char *fp3_opc_mnemonic(unsigned opc) {
  switch (opc) {
#define X(name, code, mnem, uses, unit, desc) \
  case code:                                  \
    return mnem;
    FP3_OPCODES(X)
#undef X
  default:
    return NULL;
  }
}

int fp3_opc_lookup(const char *mnemonic) {
#define X(name, code, mnem, uses, unit, desc) \
  if (strcmp(mnemonic, mnem) == 0) return code;
  FP3_OPCODES(X)
#undef X
  return -1;
}

int fp3_insn_check(uint64_t w, unsigned num_regs, unsigned imem_depth,
                   char *reason, size_t n) {
  unsigned opc = fp3_insn_opc(w);
  int uses = fp3_opc_uses(opc);
  if (uses < 0) {
    snprintf(reason, n, "unknown opcode 0x%02x", opc);
    return -1;
  }
  const char *mn = fp3_opc_mnemonic(opc);
  struct {
    unsigned bit;
    const char *name;
    unsigned value;
  } regs[3] = {{FP3_USES_RD, "rd", fp3_insn_rd(w)},
               {FP3_USES_RA, "ra", fp3_insn_ra(w)},
               {FP3_USES_RB, "rb", fp3_insn_rb(w)}};
  for (int i = 0; i < 3; i++) {
    if (!((unsigned)uses & regs[i].bit)) {
      if (regs[i].value != 0) {
        snprintf(reason, n, "%s field is %u but %s does not use it",
                 regs[i].name, regs[i].value, mn);
        return -1;
      }
    } else if (regs[i].value >= num_regs) {
      snprintf(reason, n, "%s is r%u, not below %u registers", regs[i].name,
               regs[i].value, num_regs);
      return -1;
    }
  }
  if (!((unsigned)uses & FP3_USES_IMM) && fp3_insn_imm(w) != 0) {
    snprintf(reason, n, "imm field is 0x%08x but %s does not use it",
             (unsigned)fp3_insn_imm(w), mn);
    return -1;
  }
  if (fp3_opc_has_target(opc) && fp3_insn_imm(w) >= imem_depth) {
    snprintf(reason, n, "%s target %u outside the %u-entry instruction memory", mn,
             (unsigned)fp3_insn_imm(w), imem_depth);
    return -1;
  }
  return 0;
}

int fp3_insn_check_at(uint64_t w, uint32_t pc, unsigned num_regs, unsigned imem_depth,
                      char *reason, size_t n) {
  if (fp3_insn_check(w, num_regs, imem_depth, reason, n)) return -1;
  if (fp3_insn_opc(w) == FP3_OP_BEQ && fp3_insn_imm(w) <= pc) {
    snprintf(reason, n, "beq target %u is not ahead of the beq (at %u)",
             (unsigned)fp3_insn_imm(w), (unsigned)pc);
    return -1;
  }
  return 0;
}

int fp3_opc_has_target(unsigned opc) { return opc == FP3_OP_ENDI || opc == FP3_OP_BEQ; }

int fp3_image_validate(const fp3_image *img, char *msg, size_t n) {
  char why[160];
  if (img->n > FP3_DEFAULT_IMEM_DEPTH) {
    snprintf(msg, n, "image of %zu words exceeds the %d-word instruction memory",
             img->n, FP3_DEFAULT_IMEM_DEPTH);
    return -1;
  }
  for (size_t i = 0; i < img->n; i++) {
    if (fp3_insn_check_at(img->words[i], (uint32_t)i, FP3_DEFAULT_NUM_REGS, FP3_DEFAULT_IMEM_DEPTH,
                          why, sizeof why)) {
      snprintf(msg, n, "word %zu: %s", i, why);
      return -1;
    }
  }
  for (int side = 0; side < 2; side++) {
    const fp3_binding *list = side ? img->bind_out : img->bind_in;
    const unsigned count = side ? img->nbind_out : img->nbind_in;
    for (unsigned i = 0; i < count; i++)
      if (list[i].reg >= FP3_DEFAULT_NUM_REGS) {
        snprintf(msg, n, "%s %s: register r%d out of range", side ? ".out" : ".in",
                 list[i].name, list[i].reg);
        return -1;
      }
  }
  return 0;
}

/* ---- writing ------------------------------------------------------------ */

int fp3_image_write(const fp3_image *img, const char *path,
                    const char *source, char *msg, size_t n) {
  size_t plen = strlen(path);
  char *tmp = malloc(plen + 5);
  if (!tmp) {
    snprintf(msg, n, "%s: out of memory", path);
    return -1;
  }
  memcpy(tmp, path, plen);
  memcpy(tmp + plen, ".tmp", 5);

  FILE *f = fopen(tmp, "w");
  if (!f) {
    snprintf(msg, n, "%s: %s", tmp, strerror(errno));
    free(tmp);
    return -1;
  }
  int bad = 0;
  if (fprintf(f, "// FP3 program image: %zu words of 64 bits, $readmemh format\n",
              img->n) < 0)
    bad = 1;
  if (source && fprintf(f, "// source: %s\n", source) < 0) bad = 1;
  if (img->model[0] && fprintf(f, "// .model %s\n", img->model) < 0) bad = 1;
  if (img->integrator[0] && fprintf(f, "// .integrator %s\n", img->integrator) < 0) bad = 1;
  for (unsigned i = 0; i < img->nbind_in; i++)
    if (fprintf(f, "// .in %s r%d\n", img->bind_in[i].name, img->bind_in[i].reg) < 0) bad = 1;
  for (unsigned i = 0; i < img->nbind_out; i++)
    if (fprintf(f, "// .out %s r%d\n", img->bind_out[i].name, img->bind_out[i].reg) < 0)
      bad = 1;
  for (size_t i = 0; i < img->n && !bad; i++) {
    int r;
    if (img->line[i] > 0)
      r = fprintf(f, "%016llx  // @%zu line %d\n",
                  (unsigned long long)img->words[i], i, img->line[i]);
    else
      r = fprintf(f, "%016llx  // @%zu\n", (unsigned long long)img->words[i], i);
    if (r < 0) bad = 1;
  }
  if (fflush(f) != 0 || ferror(f)) bad = 1;
  int err = errno;
  if (fclose(f) != 0 && !bad) {
    bad = 1;
    err = errno;
  }
  if (bad) {
    snprintf(msg, n, "%s: write failed: %s", tmp, strerror(err));
    remove(tmp);
    free(tmp);
    return -1;
  }
  if (rename(tmp, path) != 0) {
    snprintf(msg, n, "%s: cannot rename from %s: %s", path, tmp,
             strerror(errno));
    remove(tmp);
    free(tmp);
    return -1;
  }
  free(tmp);
  return 0;
}

/* ---- reading ------------------------------------------------------------ */

static int parse_reg_token(const char *s, int *reg) {
  if (s[0] != 'r' || !isdigit((unsigned char)s[1])) return -1;
  char *end;
  errno = 0;
  long v = strtol(s + 1, &end, 10);
  if (errno || *end != '\0' || v < 0 || v >= FP3_DEFAULT_NUM_REGS) return -1;
  *reg = (int)v;
  return 0;
}

/* A comment (text after `//`): a binding, a word's source line or free
 * text.  Returns 0 or -1 with a reason. */
static int read_comment(const char *c, fp3_image *img, int *word_line,
                        char *why, size_t n) {
  char kind[16], name[FP3_BIND_NAME_LEN + 8], reg[16], extra[2];
  while (*c == ' ' || *c == '\t') c++;
  if (c[0] == '.') {
    int k = sscanf(c, "%15s %39s %15s %1s", kind, name, reg, extra);
    if (strcmp(kind, ".model") == 0 || strcmp(kind, ".integrator") == 0) {
      const int is_model = kind[1] == 'm';
      char *dst = is_model ? img->model : img->integrator;
      const size_t cap = is_model ? sizeof img->model : sizeof img->integrator;
      const char *v = c + strlen(kind);
      while (*v == ' ' || *v == '\t') v++;
      size_t len = strcspn(v, "\r\n");
      while (len && (v[len - 1] == ' ' || v[len - 1] == '\t')) len--;
      if (k < 2 || len >= cap) {
        snprintf(why, n, "malformed %s comment '%s'", kind, c);
        return -1;
      }
      memcpy(dst, v, len);
      dst[len] = '\0';
      return 0;
    }
    int is_in = strcmp(kind, ".in") == 0, is_out = strcmp(kind, ".out") == 0;
    if (!is_in && !is_out) return 0; /* some other remark */
    int r;
    if (k != 3 || parse_reg_token(reg, &r)) {
      snprintf(why, n, "malformed binding comment '%s'", c);
      return -1;
    }
    return fp3_image_bind(img, is_in, name, r, 0, why, n);
  }
  if (c[0] == '@' && word_line) {
    unsigned long addr;
    int ln;
    if (sscanf(c, "@%lu line %d", &addr, &ln) == 2 && ln > 0) *word_line = ln;
  }
  return 0;
}

int fp3_image_read(const char *path, fp3_image *img, char *msg, size_t n) {
  fp3_image_init(img);
  FILE *f = fopen(path, "r");
  if (!f) {
    snprintf(msg, n, "%s: %s", path, strerror(errno));
    return -1;
  }
  char buf[1024], why[256];
  int lineno = 0, rc = 0;
  while (fgets(buf, sizeof buf, f)) {
    lineno++;
    size_t len = strlen(buf);
    if (len == sizeof buf - 1 && buf[len - 1] != '\n' && !feof(f)) {
      snprintf(msg, n, "%s:%d: line too long", path, lineno);
      rc = -1;
      break;
    }
    char *comment = strstr(buf, "//");
    if (comment) {
      *comment = '\0';
      comment += 2;
      comment[strcspn(comment, "\r\n")] = '\0';
    }
    char *p = buf;
    while (isspace((unsigned char)*p)) p++;
    char *e = p + strlen(p);
    while (e > p && isspace((unsigned char)e[-1])) *--e = '\0';
    if (*p == '\0') { /* comment-only or blank line */
      if (comment && read_comment(comment, img, NULL, why, sizeof why)) {
        snprintf(msg, n, "%s:%d: %s", path, lineno, why);
        rc = -1;
        break;
      }
      continue;
    }
    size_t digits = strspn(p, "0123456789abcdefABCDEF");
    if (digits != 16 || p[16] != '\0') {
      snprintf(msg, n, "%s:%d: expected one word of 16 hex digits, got '%s'",
               path, lineno, p);
      rc = -1;
      break;
    }
    if (img->n >= FP3_DEFAULT_IMEM_DEPTH) {
      snprintf(msg, n, "%s:%d: more than %d words (instruction memory size)",
               path, lineno, FP3_DEFAULT_IMEM_DEPTH);
      rc = -1;
      break;
    }
    int wl = 0;
    if (comment && read_comment(comment, img, &wl, why, sizeof why)) {
      snprintf(msg, n, "%s:%d: %s", path, lineno, why);
      rc = -1;
      break;
    }
    img->words[img->n] = strtoull(p, NULL, 16);
    img->line[img->n] = wl;
    img->n++;
  }
  if (rc == 0 && ferror(f)) {
    snprintf(msg, n, "%s: read error", path);
    rc = -1;
  }
  fclose(f);
  return rc;
}

int fp3_image_ends(const fp3_image *img) {
  for (size_t i = 0; i < img->n; i++) {
    unsigned op = fp3_insn_opc(img->words[i]);
    if (op == FP3_OP_ENDI || op == FP3_OP_HALT) return 1;
  }
  return 0;
}
