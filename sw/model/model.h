/*
 * model.h -- the model language (.fp3m, docs/models.md): equations of
 * motion as a file, parsed by hand (recursive descent) into an expression
 * DAG, with its literal golden model in C binary32 and its double-precision
 * meaning for the references (modelref.h).
 *
 *   model projectile
 *   param kd, g = 9.81           # per-object inputs (h is always one), a
 *                                # default where `= NUMBER` follows a name
 *   param h = 0.015625           # the step's default (h named only so)
 *   state x, vx = 30             # or: position x / velocity vx (the split);
 *                                # `= NUMBER`: the initial value's default
 *   const half = 0.5             # a named binary32 constant
 *   let sp = sqrt(vx*vx)         # defined before use
 *   x'  = vx                     # one equation per state variable
 *   vx' = -kd*sp*vx - g
 *   exact x = ...                # optional: the analytic solution, in t
 *
 * Literal meaning (the one the golden model and `--literal` programs
 * follow, bit for bit): every binary operator and function is one binary32
 * operation (IEEE 754-2019 §5.4.1, the cores' rounding) on its operands in
 * the tree the grammar gives; unary minus flips the sign bit (§5.5.1); a
 * number is rounded once to binary32 as strtof does (RNE).
 *
 * Expressions are stored as a DAG in one array, each node after its
 * operands: a `let` name is a reference to the node of its expression, a
 * `const` name to a number node.  Evaluating the array in index order
 * evaluates every subexpression once, operands first.
 */
#ifndef FP3_MODEL_LANG_H
#define FP3_MODEL_LANG_H

#include <stddef.h>
#include <stdint.h>

/* The constants of RK4's stages and weights (half, two, sixth), binary32,
 * as every integrator and program loads them (`li`): 1/6 is 0.16666667f,
 * the binary32 nearest to it, 0x3E2AAAAB. */
#define FP3_RK4_HALF 0.5f
#define FP3_RK4_TWO 2.0f
#define FP3_RK4_SIXTH 0.16666667f

#define FP3_MODEL_NAME_LEN  32    /* longest name + 1                       */
#define FP3_MODEL_MAX_VARS  32    /* params (h included), state variables   */
#define FP3_MODEL_MAX_DEFS  128   /* consts, lets                           */
#define FP3_MODEL_MAX_NODES 2048  /* expression nodes                       */

/* Expression node kinds.  Binary: a, b; unary: a; leaves: id or value. */
enum fp3_mexpr_kind {
  FP3_ME_NUM,    /* a number: bits (binary32, strtof) and dval (strtod)   */
  FP3_ME_PARAM,  /* param id (0 is h)                                     */
  FP3_ME_STATE,  /* state variable id (in `exact` lines: its initial value) */
  FP3_ME_TIME,   /* t, in `exact` lines only                              */
  FP3_ME_ADD, FP3_ME_SUB, FP3_ME_MUL, FP3_ME_DIV,
  FP3_ME_NEG,    /* unary minus: the sign bit flipped                     */
  FP3_ME_SQRT, FP3_ME_ABS, FP3_ME_MIN, FP3_ME_MAX,
  FP3_ME_EXP, FP3_ME_SIN, FP3_ME_COS, /* `exact` lines only (double)       */
  FP3_ME_KINDS
};

typedef struct fp3_mexpr {
  int kind;        /* enum fp3_mexpr_kind                                */
  int a, b;        /* operand nodes (-1: none)                           */
  int id;          /* PARAM, STATE                                       */
  uint32_t bits;   /* NUM: binary32 value                                */
  double dval;     /* NUM: the number read in double (the references')   */
  int exact_only;  /* 1: reads t or exp/sin/cos: never evaluated in binary32 */
} fp3_mexpr;

/* Role of a state variable for the integrators that split the state
 * (symeuler, verlet): declared by `position` / `velocity` lines. */
enum fp3_mrole { FP3_MR_STATE, FP3_MR_POSITION, FP3_MR_VELOCITY };

typedef struct fp3_model {
  char name[FP3_MODEL_NAME_LEN];      /* `model NAME`, else the file's base name */
  char file[256];                     /* path as given, for messages      */
  unsigned nparam;                    /* params, h first                  */
  char param[FP3_MODEL_MAX_VARS][FP3_MODEL_NAME_LEN];
  int param_line[FP3_MODEL_MAX_VARS]; /* declaring line (0 for h)         */
  /* Defaults: `param k = 40` (h: `param h = 0.015625`), `position x =
   * 0.5`.  has_def 1 where the file gives one; def is the number as
   * strtof reads it (binary32, RNE, the sign a flipped sign bit), def_d
   * as strtod does.  The run's values are these unless --set gives
   * others (fp3_model_args_values, sw/cli/cmd_model.h); they are not
   * part of the equations, so no compiled program depends on them.
   * param_def_line: the line giving a param's default (for h the `param
   * h = NUMBER` line; 0 without one). */
  unsigned char param_has_def[FP3_MODEL_MAX_VARS];
  float param_def[FP3_MODEL_MAX_VARS];
  double param_def_d[FP3_MODEL_MAX_VARS];
  int param_def_line[FP3_MODEL_MAX_VARS];
  unsigned nstate;
  char state[FP3_MODEL_MAX_VARS][FP3_MODEL_NAME_LEN];
  int state_line[FP3_MODEL_MAX_VARS];
  unsigned char state_has_def[FP3_MODEL_MAX_VARS]; /* the initial value's default, */
  float state_def[FP3_MODEL_MAX_VARS];             /* as the params' above       */
  double state_def_d[FP3_MODEL_MAX_VARS];
  int role[FP3_MODEL_MAX_VARS];       /* enum fp3_mrole                   */
  int deriv[FP3_MODEL_MAX_VARS];      /* node of NAME' (every one set)    */
  int exact[FP3_MODEL_MAX_VARS];      /* node of `exact NAME`, -1: none   */
  unsigned ndef;                      /* consts and lets, in file order   */
  char def[FP3_MODEL_MAX_DEFS][FP3_MODEL_NAME_LEN];
  int def_node[FP3_MODEL_MAX_DEFS];
  int def_is_let[FP3_MODEL_MAX_DEFS];
  unsigned nn;
  fp3_mexpr node[FP3_MODEL_MAX_NODES];
} fp3_model;

/* Parse model text `src` (NUL-terminated); `file` names it in messages and
 * in m->file.  Returns 0, or -1 with "FILE:LINE:COL: reason" in msg:
 * syntax errors, unknown names, a name declared twice or reserved (h, t,
 * function names; h may be named once, on a param line, with a default),
 * a state variable with no equation or two, a let that refers to itself
 * or to a later let (a cycle or use before definition), more names or
 * nodes than the limits above, a default that is not a signed number or
 * not finite in binary32 or given twice, a default step h <= 0. */
int fp3_model_parse(const char *src, const char *file, fp3_model *m, char *msg, size_t n);

/* Read and parse a file (fp3_model_parse); "FILE: cannot read" on I/O errors. */
int fp3_model_load(const char *path, fp3_model *m, char *msg, size_t n);

/* Index of param / state `name`, or -1. */
int fp3_model_param(const fp3_model *m, const char *name);
int fp3_model_state(const fp3_model *m, const char *name);

/* 1 if any equation (after lets and consts) uses an operation of `kind`
 * (e.g. FP3_ME_SQRT), else 0. */
int fp3_model_uses(const fp3_model *m, int kind);

/* 1 if the state is split into positions and velocities (a `position` and
 * a `velocity` line, every state variable in one of them). */
int fp3_model_split(const fp3_model *m);

/* 1 if velocity Verlet applies: the state is split (fp3_model_split) and
 * no velocity's derivative (the acceleration) reads a velocity, directly
 * or through lets.  Else 0, and (if not NULL) *vel the first velocity
 * whose derivative reads velocity *reads (an unsplit model: 0 with
 * neither set). */
int fp3_model_verlet_ok(const fp3_model *m, unsigned *vel, unsigned *reads);

/* The operation a node kind stands for, as written ("+", "sqrt", ...). */
const char *fp3_mexpr_op_name(int kind);

/* ---- the literal golden model (C binary32) ------------------------------- */

/* Integrators of the literal golden model: "euler rk2 rk4 rk4comp symeuler
 * verlet rk4se rk4secomp rk4vs rk4vscomp verletp" (fp3_model_step_literal
 * defines each). */
const char *fp3_model_integrators(void);
int fp3_model_integrator_known(const char *name);

/* 1 if integrator `integ` is defined for model m's shape: symeuler,
 * rk4se, rk4secomp, rk4vs and rk4vscomp need the split state
 * (fp3_model_split), verlet fp3_model_verlet_ok, verletp the split state
 * with every position's derivative a velocity (fp3_model_pair); the
 * others take any model.  0 for an unknown name. */
int fp3_model_integrator_applies(const fp3_model *m, const char *integ);

/* Values an integration of `integ` carries from one integration to the
 * next: nstate, or 2 nstate for rk4comp, rk4secomp, rk4vscomp (a Kahan
 * compensation per state variable after the state) and verletp (an
 * acceleration per velocity after the state; 0 in a position's slot). */
unsigned fp3_model_carried(const fp3_model *m, const char *integ);

/* The velocity that position `pos` moves with, when its derivative is
 * exactly that state variable (x' = u); else -1. */
int fp3_model_pair(const fp3_model *m, unsigned pos);

/* Start a literal integration: y holds the initial state (nstate values)
 * and gets the other carried values (fp3_model_carried): compensations 0,
 * verletp's accelerations f_u(y), in the caller's FP environment. */
void fp3_model_start_literal(const fp3_model *m, const char *integ, const float *in,
                             float *y);

/* Derivatives f(y) of the model in binary32, the tree's operations in the
 * literal meaning; in[] holds h and the params (in[0] = h), y the state;
 * f gets nstate values.  val: scratch of m->nn floats. */
void fp3_model_eval_f(const fp3_model *m, const float *in, const float *y, float *f,
                      float *val);

/* One literal integration of y (nstate values) with integrator `name`
 * (docs/models.md gives each as C):
 *   euler:    y_i += h f_i(y)
 *   rk2:      ym_j = y_j + (0.5 h) f_j(y);  y_i += h f_i(ym)
 *   rk4:      k1 = h f(y), k2 = h f(y + 0.5 k1), k3 = h f(y + 0.5 k2),
 *             k4 = h f(y + k3), y_i += 0.16666667 (((k1 + 2 k2) + 2 k3) + k4)
 *   rk4comp:  rk4 with the update y_i += d_i Kahan-compensated (Kahan
 *             1965; as the ship's rk4comp, sw/ref/integrators.c): with c_i
 *             carried from one integration to the next (0 at the start),
 *             yk = d_i - c_i; t = y_i + yk; c_i = (t - y_i) - yk; y_i = t.
 *             y holds 2 nstate values: the state, then the c_i
 *   symeuler: velocities u_i += h f_i(y), then positions
 *             x_i += h f_i(x, u_new) (needs fp3_model_split)
 *   verlet:   velocity Verlet (kick, drift, kick; Verlet 1967, Swope et
 *             al. 1982): hh = 0.5 h; u_i += hh f_i(y); x_i += h f_i(x,
 *             u); u_i += hh f_i(x, u) at the new x (needs
 *             fp3_model_verlet_ok: accelerations free of velocities;
 *             second order, symplectic, time-reversible)
 * The split-state forms of the paper's ship programs (programs/ship_*.s;
 * velocities u, positions x; sixth = 0.16666667):
 *   rk4se:    the velocities by rk4 with the positions held, then the
 *             positions by the new velocities, x_i += h f_i(x, u_new)
 *             (the paper's RK4: first order in position)
 *   rk4secomp: rk4se with every update y_i += d_i Kahan-compensated as
 *             rk4comp's
 *   rk4vs:    rk4 on every state variable, each position's increment
 *             (h sixth) ((f1 + 2 (f2 + f3)) + f4) of its derivatives at
 *             the four stages (h sixth computed once)
 *   rk4vscomp: rk4vs with the updates Kahan-compensated
 *   verletp:  velocity Verlet for velocity-dependent forces, with an
 *             Euler-predicted velocity (needs every position's derivative
 *             a velocity, x' = u): a carried (a = f_u(y) at the start),
 *             hh = 0.5 h, hh2 = 0.5 (h h); x_i += (h u + hh2 a);
 *             up = u + h a; u += hh (a + f_u(x_new, up)); a = f_u(y_new)
 * y holds fp3_model_carried values (fp3_model_start_literal fills them).
 * Each product and sum one binary32 operation, in the order written.
 * Returns 0, or -1 for an unknown integrator or one that does not apply
 * to m (fp3_model_integrator_applies).  Runs in the caller's FP environment (fpenv_enter for RTZ/FTZ). */
int fp3_model_step_literal(const fp3_model *m, const char *integrator, const float *in,
                           float *y);

/* min(a, b) (want_max 0) or max(a, b) (1) in binary32: IEEE 754-2019
 * §9.6 minimum and maximum (a NaN operand gives a NaN: a quieted if a is a
 * NaN, else b quieted; -0 is below +0; otherwise the smaller or larger
 * operand, exactly), as the processor's min and max (docs/fp-cores.md).
 * The one definition every golden model uses. */
float fp3_model_minmax32(float a, float b, int want_max);

/* ---- double precision ------------------------------------------------------ */

/* f(y) in double, numbers by their strtod value (dval), params in[]. */
void fp3_model_eval_f_double(const fp3_model *m, const double *in, const double *y,
                             double *f, double *val);

/* The `exact` solution of state variable i at time t from initial state
 * y0, params in[] (double); returns 0, or -1 when the model gives none. */
int fp3_model_exact(const fp3_model *m, unsigned i, const double *in, const double *y0,
                    double t, double *out);

#endif /* FP3_MODEL_LANG_H */
