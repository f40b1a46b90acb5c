/* lua_bindings.c - the only code that touches the Lua stack.
 *
 * The C side of the DSL: a model userdata with the methods block, contacts,
 * interface, load, solve and stats, and a solution userdata for drawing.
 * Every constructor takes one table of named fields; unknown fields, wrong
 * types and bad values are errors that name the function and the field.
 * All checks happen before the model is touched, so a rejected call leaves
 * it as it was.  The Lua half of the module (lua/blocklim.lua) keeps the
 * current model and turns these methods into the global commands. */
#include "lua_bindings.h"

#include <lauxlib.h>
#include <lualib.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "assoc.h"
#include "mpec.h"
#include "vtk.h"
#include "seqlp.h"
#include "contact.h"
#include "draw.h"
#include "model.h"
#include "solution.h"

#define MODEL_MT "blocklim.model"
#define SOLUTION_MT "blocklim.solution"
#define LAST_RESULT "blocklim.last"

/* ---- argument checking ------------------------------------------------- */

/* Raises a Lua error with a printf-formatted message and no position prefix:
 * the message itself names the function and the field. */
static int fail(lua_State *L, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int fail(lua_State *L, const char *fmt, ...)
{
    char msg[1200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    lua_pushstring(L, msg);
    return lua_error(L);
}

/* An error of the core met in command cmd: its message, which starts with
 * the command's name or else with the step's (the detection's
 * "contacts: ..."), after the command's. */
static int fail_in(lua_State *L, const char *cmd, const char *msg)
{
    size_t n = strlen(cmd);
    if (strncmp(msg, cmd, n) == 0 && msg[n] == ':') return fail(L, "%s", msg);
    return fail(L, "%s: %s", cmd, msg);
}

/* A model method of one table of fields (m:block{}, ...) given more. */
static void one_table(lua_State *L, const char *fn)
{
    if (lua_gettop(L) > 2) fail(L, "%s: takes one table of fields, got %d arguments", fn, lua_gettop(L) - 1);
}

/* An omitted table argument at idx (the last one) reads as {}. */
static void opt_table(lua_State *L, int idx)
{
    if (lua_isnoneornil(L, idx)) {
        lua_settop(L, idx - 1);
        lua_newtable(L);
    }
}

/* Raises an error for the first key of table idx that is neither one of the
 * names in allowed (NULL-terminated) nor a positional index 1..npos. */
static void check_fields(lua_State *L, int idx, const char *fn, const char *const *allowed, int npos)
{
    if (!lua_istable(L, idx))
        fail(L, "%s: expects a table of named fields, got %s", fn, luaL_typename(L, idx));
    lua_pushnil(L);
    while (lua_next(L, idx)) {
        lua_pop(L, 1);
        if (lua_type(L, -1) == LUA_TSTRING) {
            const char *k = lua_tostring(L, -1);
            int ok = 0;
            for (const char *const *a = allowed; *a && !ok; a++) ok = strcmp(*a, k) == 0;
            if (!ok) {
                char list[256] = "";
                for (const char *const *a = allowed; *a; a++) {
                    size_t len = strlen(list);
                    snprintf(list + len, sizeof list - len, "%s%s", a != allowed ? ", " : "", *a);
                }
                lua_rawgeti(L, idx, 1);
                int unnamed = lua_isnil(L, -1);
                lua_pop(L, 1);
                if (npos == 2 && unnamed) /* interface{ a = 1, b = 2 }: the blocks are unnamed */
                    fail(L, "%s: unknown field '%s' (fields: %s; the two blocks come first, "
                            "unnamed: %s{ 3, 7, ... })", fn, k, list, fn);
                fail(L, "%s: unknown field '%s' (fields: %s)", fn, k, list);
            }
        } else if (lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 1 &&
                   lua_tointeger(L, -1) <= npos) {
            continue;
        } else if (lua_isinteger(L, -1) && npos > 0) {
            fail(L, "%s: unexpected entry [%lld]: the table takes %d unnamed entr%s, then named fields",
                 fn, (long long)lua_tointeger(L, -1), npos, npos == 1 ? "y" : "ies");
        } else {
            fail(L, "%s: unexpected %s key in the table (fields are named)", fn,
                       luaL_typename(L, -1));
        }
    }
}

/* Pushes field f of table idx; returns 0 (and pushes nothing) if it is nil. */
static int field(lua_State *L, int idx, const char *f)
{
    if (lua_getfield(L, idx, f) == LUA_TNIL) {
        lua_pop(L, 1);
        return 0;
    }
    return 1;
}

/* 1 when field f of table idx is present (not nil). */
static int field_given(lua_State *L, int idx, const char *f)
{
    int given = lua_getfield(L, idx, f) != LUA_TNIL;
    lua_pop(L, 1);
    return given;
}

enum { ANY = 0, NONNEG = 1, POSITIVE = 2 };

/* Reads number field f, or returns def when absent. */
static double number_field(lua_State *L, int idx, const char *fn, const char *f, double def,
                           int sign)
{
    if (!field(L, idx, f)) return def;
    if (!lua_isnumber(L, -1) || lua_type(L, -1) == LUA_TSTRING)
        fail(L, "%s: field '%s' must be a number, got %s", fn, f, luaL_typename(L, -1));
    double v = lua_tonumber(L, -1);
    lua_pop(L, 1);
    if (isnan(v)) fail(L, "%s: field '%s' is not a number (nan)", fn, f);
    if (sign == NONNEG && v < 0) fail(L, "%s: field '%s' must be >= 0, got %g", fn, f, v);
    if (sign == POSITIVE && !(v > 0))
        fail(L, "%s: field '%s' must be > 0, got %g", fn, f, v);
    if (sign != ANY && isinf(v) && strcmp(f, "mu") != 0)
        fail(L, "%s: field '%s' must be finite", fn, f);
    return v;
}

/* Field 'mu' of command fn: >= 0, at most BL_MU_MAX or infinite. */
static double mu_field(lua_State *L, int idx, const char *fn, double def)
{
    double v = number_field(L, idx, fn, "mu", def, NONNEG);
    if (isfinite(v) && v > BL_MU_MAX)
        fail(L, "%s: field 'mu' must be at most %g, or math.huge for joints that never slide, got %g", fn,
             BL_MU_MAX, v);
    return v;
}

static int boolean_field(lua_State *L, int idx, const char *fn, const char *f, int def)
{
    if (!field(L, idx, f)) return def;
    if (!lua_isboolean(L, -1))
        fail(L, "%s: field '%s' must be true or false, got %s", fn, f, luaL_typename(L, -1));
    int v = lua_toboolean(L, -1);
    lua_pop(L, 1);
    return v;
}

/* Coordinate i (0-based) of the point of n coordinates on the top of the
 * stack, which must be a finite number: else the message says which one,
 * and what it is. */
static double coordinate(lua_State *L, const char *fn, const char *what, int i, int n)
{
    static const char *const names[] = {"x", "y", "z"};
    const char *form = n == 3 ? "{x, y, z} of three finite numbers" : "{x, y} of two finite numbers";
    lua_geti(L, -1, i + 1);
    int type = lua_type(L, -1);
    double v = lua_tonumber(L, -1);
    if (type == LUA_TNIL) fail(L, "%s: %s must be a point %s, its %s is missing", fn, what, form, names[i]);
    if (type != LUA_TNUMBER)
        fail(L, "%s: %s must be a point %s, its %s is a %s", fn, what, form, names[i], luaL_typename(L, -1));
    if (!isfinite(v))
        fail(L, "%s: %s must be a point %s, its %s is %s", fn, what, form, names[i],
             isnan(v) ? "nan" : v > 0 ? "inf" : "-inf");
    lua_pop(L, 1);
    return v;
}

/* Reads the value on top of the stack as a point {x, y}; pops it. */
static bl_vec2 to_point(lua_State *L, const char *fn, const char *what)
{
    if (!lua_istable(L, -1))
        fail(L, "%s: %s must be a point {x, y}, got %s", fn, what, luaL_typename(L, -1));
    double x = coordinate(L, fn, what, 0, 2), y = coordinate(L, fn, what, 1, 2);
    if (lua_rawlen(L, -1) != 2)
        fail(L, "%s: %s must be a point {x, y} of two numbers, got %d", fn, what,
                   (int)lua_rawlen(L, -1));
    lua_pop(L, 1);
    return bl_v2(x, y);
}

/* The length of the list on the top of the stack, which must have no other
 * entries: a point left out ({[1] = p, [2] = q, [3] = r, [5] = s}) cut the
 * list at 3 without a word. */
static int list_length(lua_State *L, const char *fn, const char *what)
{
    int n = (int)lua_rawlen(L, -1), count = 0, other = 0;
    lua_Integer top = 0;
    lua_pushnil(L);
    while (lua_next(L, -2)) {
        lua_pop(L, 1);
        count++;
        if (lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 1) {
            if (lua_tointeger(L, -1) > top) top = lua_tointeger(L, -1);
        } else {
            other = 1;
        }
    }
    if (count == n && top == n && !other) return n;
    if (other) return fail(L, "%s: %s must be a list of entries 1 to n, without other keys", fn, what);
    lua_Integer missing = 1; /* the first of 1..top that is not there */
    while (lua_rawgeti(L, -1, missing) != LUA_TNIL && missing < top) lua_pop(L, 1), missing++;
    lua_pop(L, 1);
    return fail(L, "%s: %s must be a list of entries 1 to n; entry %lld is missing", fn, what,
                (long long)missing);
}

/* The point {x, y, z} on the top of the stack (popped). */
static bl_vec3 to_point3(lua_State *L, const char *fn, const char *what)
{
    if (!lua_istable(L, -1))
        fail(L, "%s: %s must be a point {x, y, z}, got %s", fn, what, luaL_typename(L, -1));
    double c[3];
    for (int i = 0; i < 3; i++) c[i] = coordinate(L, fn, what, i, 3);
    if (lua_rawlen(L, -1) != 3)
        fail(L, "%s: %s must be a point {x, y, z} of three numbers, got %d", fn, what,
             (int)lua_rawlen(L, -1));
    lua_pop(L, 1);
    return bl_v3(c[0], c[1], c[2]);
}

static int point_field(lua_State *L, int idx, const char *fn, const char *f, bl_vec2 *out)
{
    if (!field(L, idx, f)) return 0;
    char what[64];
    snprintf(what, sizeof what, "field '%s'", f);
    *out = to_point(L, fn, what);
    return 1;
}

/* Options with fixed choices: returns the index of the choice; also, where
 * not NULL, what else the field may be, for the message. */
static int choice_field_or(lua_State *L, int idx, const char *fn, const char *f,
                           const char *const *choices, int def, const char *also)
{
    if (!field(L, idx, f)) return def;
    const char *s = lua_tostring(L, -1);
    for (int i = 0; s && lua_type(L, -1) == LUA_TSTRING && choices[i]; i++)
        if (strcmp(s, choices[i]) == 0) {
            lua_pop(L, 1);
            return i;
        }
    char list[256] = "";
    for (int i = 0; choices[i]; i++) {
        size_t len = strlen(list);
        snprintf(list + len, sizeof list - len, "%s\"%s\"", i ? ", " : "", choices[i]);
    }
    return fail(L, "%s: field '%s' must be one of %s%s%s, got %s", fn, f, list, also ? ", or " : "",
                also ? also : "", luaL_tolstring(L, -1, NULL));
}
static int choice_field(lua_State *L, int idx, const char *fn, const char *f,
                        const char *const *choices, int def)
{
    return choice_field_or(L, idx, fn, f, choices, def, NULL);
}

/* load{}'s dead and live given by name: what else they may be */
static int load_choice(lua_State *L, int live, const char *const *choices)
{
    return choice_field_or(L, 2, "load", live ? "live" : "dead", choices, 0,
                           live ? "a table: a point load { block, at, force } or a distributed load "
                                  "{ over, q }"
                                : "a table: a point load { block, at, force }, a carried weight "
                                  "{ block, at, weight } or a distributed load { over, q }");
}

static bl_model *check_model(lua_State *L, int idx)
{
    bl_model **p = luaL_testudata(L, idx, MODEL_MT);
    if (!p) { /* m.solve{...} for m:solve{...} */
        lua_Debug ar;
        const char *name = lua_getstack(L, 0, &ar) && lua_getinfo(L, "n", &ar) && ar.name
                               ? ar.name : "model method";
        if (strcmp(name, "model method") == 0) /* its name is not known (m.load{...}) */
            fail(L, "model method: expects a model, got %s; call model methods with a colon, "
                    "as in m:block_info(1)", luaL_typename(L, idx));
        fail(L, "%s: expects a model, got %s; call it with a colon: m:%s{...}", name,
             luaL_typename(L, idx), name);
    }
    if (!*p) /* its finalizer ran: brought back by another finalizer, or called by hand */
        fail(L, "model: this model was collected (its finalizer has run); build it again");
    return *p;
}

/* A block number given by the user (1-based) -> index. */
static int block_index(lua_State *L, bl_model *m, int idx, const char *fn, const char *what)
{
    int whole = 0; /* 2.0 counts as 2; "2" not, as no number field takes a string */
    lua_Integer b = lua_type(L, idx) == LUA_TNUMBER ? lua_tointegerx(L, idx, &whole) : 0;
    if (!whole && lua_type(L, idx) == LUA_TNUMBER)
        fail(L, "%s: %s must be a whole block number, got %g", fn, what, lua_tonumber(L, idx));
    if (!whole) fail(L, "%s: %s must be a block number, got %s", fn, what, luaL_typename(L, idx));
    if (m->nblocks == 0)
        fail(L, "%s: %s is block %lld, but the model has no blocks yet", fn, what, (long long)b);
    if (b < 1 || b > m->nblocks)
        fail(L, "%s: %s is block %lld, but the model has blocks 1 to %d", fn, what, (long long)b,
                   m->nblocks);
    return (int)b - 1;
}

/* ---- small setters for result tables ------------------------------------ */

static void set_number(lua_State *L, const char *k, double v)
{
    lua_pushnumber(L, v);
    lua_setfield(L, -2, k);
}

static void set_integer(lua_State *L, const char *k, lua_Integer v)
{
    lua_pushinteger(L, v);
    lua_setfield(L, -2, k);
}

static void set_boolean(lua_State *L, const char *k, int v)
{
    lua_pushboolean(L, v);
    lua_setfield(L, -2, k);
}

static void set_string(lua_State *L, const char *k, const char *v)
{
    lua_pushstring(L, v);
    lua_setfield(L, -2, k);
}

static void push_pair(lua_State *L, double a, double b)
{
    lua_createtable(L, 2, 0);
    lua_pushnumber(L, a);
    lua_rawseti(L, -2, 1);
    lua_pushnumber(L, b);
    lua_rawseti(L, -2, 2);
}

static void push_point(lua_State *L, bl_vec2 p) { push_pair(L, p.x, p.y); }

static void push_triple(lua_State *L, bl_vec3 p)
{
    lua_createtable(L, 3, 0);
    lua_pushnumber(L, p.x);
    lua_rawseti(L, -2, 1);
    lua_pushnumber(L, p.y);
    lua_rawseti(L, -2, 2);
    lua_pushnumber(L, p.z);
    lua_rawseti(L, -2, 3);
}

/* ---- model -------------------------------------------------------------- */

/* How a 3D interface carries force: names of bl_interface_model, in order. */
static const char *const interface_models[] = {"vertex", "resultant", NULL};

static int model_new(lua_State *L)
{
    static const char *const fields[] = {"name", "dim", "mu", "cohesion", "density",
                                         "thickness", "gravity", "interface", "mu_t", NULL};
    check_fields(L, 1, "model", fields, 0);
    double dim = number_field(L, 1, "model", "dim", 2, POSITIVE);
    if (dim != 2 && dim != 3) fail(L, "model: field 'dim' must be 2 or 3, got %g", dim);
    if (dim == 3 && field_given(L, 1, "thickness"))
        fail(L, "model: field 'thickness' is for 2D models (a 3D block is solid)");
    if (dim == 2 && (field_given(L, 1, "interface") || field_given(L, 1, "mu_t")))
        fail(L, "model: fields 'interface' and 'mu_t' are for 3D models (in 2D the vertex and "
                "resultant models are the same)");
    int imodel = choice_field(L, 1, "model", "interface", interface_models, 0);
    double mut = number_field(L, 1, "model", "mu_t", 0.0, POSITIVE);
    if (field_given(L, 1, "mu_t") && imodel != BL_RESULTANT)
        fail(L, "model: field 'mu_t' goes with interface = \"resultant\"");
    bl_vec3 g3 = bl_v3(0, 0, -1);
    if (dim == 3 && field(L, 1, "gravity")) {
        g3 = to_point3(L, "model", "field 'gravity'");
        g3 = bl_v3_unit(g3);
        if (bl_v3_norm(g3) == 0) fail(L, "model: field 'gravity' must be a non-zero direction");
    }
    const char *name = "";
    if (field(L, 1, "name")) {
        if (lua_type(L, -1) != LUA_TSTRING)
            fail(L, "model: field 'name' must be a string, got %s", luaL_typename(L, -1));
        name = lua_tostring(L, -1);
        lua_pop(L, 1);
    }
    double mu = mu_field(L, 1, "model", 0.65);
    double c = number_field(L, 1, "model", "cohesion", 0.0, NONNEG);
    double rho = number_field(L, 1, "model", "density", 1.0, POSITIVE);
    double th = number_field(L, 1, "model", "thickness", 1.0, POSITIVE);
    bl_vec2 g = bl_v2(0, -1);
    if (dim == 2 && point_field(L, 1, "model", "gravity", &g) && bl_v2_norm(g) == 0)
        fail(L, "model: field 'gravity' must be a non-zero direction");

    bl_model **p = lua_newuserdatauv(L, sizeof *p, 0);
    *p = NULL;
    luaL_setmetatable(L, MODEL_MT);
    *p = bl_model_new();
    if (!*p) return fail(L, "model: out of memory");
    bl_model *m = *p;
    m->dim = (int)dim;
    m->interface_model = (bl_interface_model)imodel;
    m->mu_t = mut;
    snprintf(m->name, sizeof m->name, "%s", name);
    m->mu = mu;
    m->cohesion = c;
    m->density = rho;
    m->thickness = th;
    m->gravity = bl_v2_unit(g);
    m->gravity3 = g3;
    return 1;
}

static int model_gc(lua_State *L)
{
    bl_model **p = luaL_checkudata(L, 1, MODEL_MT);
    bl_model_free(*p);
    *p = NULL;
    return 0;
}

static int model_tostring(lua_State *L)
{
    bl_model *m = check_model(L, 1);
    int nfree = bl_model_free_blocks(m);
    char mu[32];
    snprintf(mu, sizeof mu, "%g", m->mu);
    lua_pushfstring(L, "model%s%s: %d free block%s, %d support%s, mu = %s", m->name[0] ? " " : "",
                    m->name, nfree, nfree == 1 ? "" : "s", m->nblocks - nfree,
                    m->nblocks - nfree == 1 ? "" : "s", mu);
    if (m->contacts_valid)
        lua_pushfstring(L, ", %d interface%s", m->ninterfaces, m->ninterfaces == 1 ? "" : "s");
    else lua_pushstring(L, "");
    lua_concat(L, 2);
    return 1;
}

/* block{} in a 3D model: vertices {x, y, z} and faces (lists of vertex
 * numbers), or points whose convex hull is the block. */
static int block_3d(lua_State *L, bl_model *m)
{
    if (field_given(L, 2, "thickness"))
        return fail(L, "block: field 'thickness' is for 2D models; a 3D block is solid");
    int hull = field_given(L, 2, "points");
    if (hull == (field_given(L, 2, "vertices") || field_given(L, 2, "faces")))
        return fail(L, "block: a 3D block needs 'vertices' and 'faces', or 'points' (its convex "
                       "hull)");
    const char *list = hull ? "points" : "vertices";
    field(L, 2, list);
    if (!lua_istable(L, -1))
        return fail(L, "block: field '%s' must be a list of points {x, y, z}, got %s", list,
                    luaL_typename(L, -1));
    char whole[32];
    snprintf(whole, sizeof whole, "field '%s'", list);
    int nv = list_length(L, "block", whole), vt = lua_gettop(L);
    if (nv < 4) return fail(L, "block: field '%s' needs at least 4 points, got %d", list, nv);
    bl_vec3 *v = lua_newuserdatauv(L, (size_t)nv * sizeof *v, 0); /* scratch, owned by Lua */
    for (int i = 0; i < nv; i++) {
        char what[64];
        snprintf(what, sizeof what, "field '%s' point %d", list, i + 1);
        lua_geti(L, vt, i + 1);
        v[i] = to_point3(L, "block", what);
    }
    int support = boolean_field(L, 2, "block", "support", 0);
    double rho = number_field(L, 2, "block", "density", 0.0, POSITIVE);
    double resolution = number_field(L, 2, "block", "resolution", 0.0, NONNEG);
    bl_polyhedron solid;
    bl_error err;
    if (hull) {
        if (bl_convex_hull(v, nv, m->nblocks + 1, &solid, &err)) return fail(L, "%s", err.msg);
    } else {
        if (!field(L, 2, "faces"))
            return fail(L, "block: field 'faces' is missing: a 3D block of 'vertices' needs its "
                           "faces (lists of vertex numbers); 'points' alone make a convex hull");
        if (!lua_istable(L, -1))
            return fail(L, "block: field 'faces' must be a list of faces (lists of vertex "
                           "numbers), got %s", luaL_typename(L, -1));
        int nf = (int)lua_rawlen(L, -1), ft = lua_gettop(L), total = 0;
        for (int k = 1; k <= nf; k++) {
            if (lua_geti(L, ft, k) != LUA_TTABLE)
                return fail(L, "block: field 'faces' face %d must be a list of vertex numbers, "
                               "got %s", k, luaL_typename(L, -1));
            total += (int)lua_rawlen(L, -1);
            lua_pop(L, 1);
        }
        int *fs = lua_newuserdatauv(L, ((size_t)nf + 1) * sizeof *fs, 0);
        int *fi = lua_newuserdatauv(L, ((size_t)total + 1) * sizeof *fi, 0);
        fs[0] = 0;
        for (int k = 1, t = 0; k <= nf; k++) {
            lua_geti(L, ft, k);
            int len = (int)lua_rawlen(L, -1);
            for (int i = 1; i <= len; i++, t++) {
                lua_geti(L, -1, i);
                lua_Number q = lua_tonumber(L, -1);
                if (lua_type(L, -1) == LUA_TNUMBER && !lua_isinteger(L, -1) && q != floor(q))
                    return fail(L, "block: field 'faces' face %d entry %d must be a whole vertex "
                                   "number, got %g", k, i, q);
                if (lua_type(L, -1) != LUA_TNUMBER)
                    return fail(L, "block: field 'faces' face %d entry %d must be a vertex "
                                   "number, got %s", k, i, luaL_typename(L, -1));
                if (q < 1 || q > nv)
                    return fail(L, "block: field 'faces' face %d names vertex %g; there are %d",
                                k, q, nv);
                fi[t] = (int)q - 1;
                lua_pop(L, 1);
            }
            fs[k] = fs[k - 1] + len;
            lua_pop(L, 1);
        }
        if (bl_polyhedron_make(&solid, v, nv, fs, fi, nf)) return fail(L, "block: out of memory");
    }
    if (bl_model_add_solid(m, &solid, support, rho, &err)) return fail(L, "%s", err.msg);
    m->blocks[m->nblocks - 1].resolution = resolution;
    lua_pushinteger(L, m->nblocks);
    return 1;
}

static int model_block(lua_State *L)
{
    static const char *const fields[] = {"vertices", "support", "density",    "thickness",
                                         "faces",    "points",  "resolution", NULL};
    bl_model *m = check_model(L, 1);
    one_table(L, "block");
    check_fields(L, 2, "block", fields, 0);
    if (m->dim == 3) return block_3d(L, m);
    if (field_given(L, 2, "faces") || field_given(L, 2, "points"))
        return fail(L, "block: fields 'faces' and 'points' are for 3D models (model{ dim = 3 })");
    if (!field(L, 2, "vertices"))
        return fail(L, "block: field 'vertices' is missing (a list of points {x, y})");
    if (!lua_istable(L, -1))
        return fail(L, "block: field 'vertices' must be a list of points, got %s",
                          luaL_typename(L, -1));
    int nv = list_length(L, "block", "field 'vertices'");
    if (nv < 3) return fail(L, "block: field 'vertices' needs at least 3 points, got %d", nv);
    int vt = lua_gettop(L);
    bl_vec2 *v = lua_newuserdatauv(L, (size_t)nv * sizeof *v, 0); /* scratch, owned by Lua */
    for (int i = 0; i < nv; i++) {
        char what[64];
        snprintf(what, sizeof what, "field 'vertices' point %d", i + 1);
        lua_geti(L, vt, i + 1);
        v[i] = to_point(L, "block", what);
    }
    int support = boolean_field(L, 2, "block", "support", 0);
    double rho = number_field(L, 2, "block", "density", 0.0, POSITIVE);
    double th = number_field(L, 2, "block", "thickness", 0.0, POSITIVE);
    double resolution = number_field(L, 2, "block", "resolution", 0.0, NONNEG);
    bl_error err;
    if (bl_model_add_block(m, v, nv, support, rho, th, &err))
        return fail(L, "%s", err.msg); /* "block N: ..." */
    m->blocks[m->nblocks - 1].resolution = resolution;
    lua_pushinteger(L, m->nblocks);
    return 1;
}

static int model_contacts(lua_State *L)
{
    static const char *const fields[] = {"tol", "gap", NULL};
    bl_model *m = check_model(L, 1);
    one_table(L, "contacts");
    opt_table(L, 2);
    check_fields(L, 2, "contacts", fields, 0);
    double tol = number_field(L, 2, "contacts", "tol", m->contact_tol, NONNEG);
    double gap = number_field(L, 2, "contacts", "gap", m->contact_gap, NONNEG);
    if (field(L, 2, "gap")) {
        lua_pop(L, 1);
        if (gap == 0) gap = -1; /* an explicit 0 switches the near-miss check off */
    }
    double old_tol = m->contact_tol, old_gap = m->contact_gap;
    m->contact_tol = tol;
    m->contact_gap = gap;
    bl_error err;
    if (bl_contact_detect(m, &err)) {
        m->contact_tol = old_tol;
        m->contact_gap = old_gap;
        if (old_tol != tol || old_gap != gap) bl_contact_detect(m, NULL);
        return fail(L, "%s", err.msg);
    }
    lua_pushinteger(L, m->ninterfaces);
    return 1;
}

static int model_interface(lua_State *L)
{
    static const char *const fields[] = {"mu", "cohesion", "points", "model", "mu_t", NULL};
    bl_model *m = check_model(L, 1);
    one_table(L, "interface");
    check_fields(L, 2, "interface", fields, 2);
    bl_joint_spec s = {0};
    lua_geti(L, 2, 1);
    s.a = block_index(L, m, -1, "interface", "entry 1");
    lua_geti(L, 2, 2);
    s.b = block_index(L, m, -1, "interface", "entry 2");
    lua_pop(L, 2);
    if (s.a == s.b) return fail(L, "interface: entries 1 and 2 are the same block %d", s.a + 1);
    if (m->blocks[s.a].support && m->blocks[s.b].support)
        return fail(L, "interface: blocks %d and %d are both supports", s.a + 1, s.b + 1);
    s.has_mu = field(L, 2, "mu") ? (lua_pop(L, 1), 1) : 0;
    s.mu = mu_field(L, 2, "interface", 0);
    s.has_cohesion = field(L, 2, "cohesion") ? (lua_pop(L, 1), 1) : 0;
    s.cohesion = number_field(L, 2, "interface", "cohesion", 0, NONNEG);
    if (m->dim == 2 && (field_given(L, 2, "model") || field_given(L, 2, "mu_t")))
        return fail(L, "interface: fields 'model' and 'mu_t' are for 3D models (in 2D the vertex "
                       "and resultant models are the same)");
    s.has_imodel = field_given(L, 2, "model");
    s.imodel = (bl_interface_model)choice_field(L, 2, "interface", "model", interface_models,
                                                m->interface_model);
    s.has_mu_t = field_given(L, 2, "mu_t");
    s.mu_t = number_field(L, 2, "interface", "mu_t", 0.0, POSITIVE);
    if (s.has_mu_t && s.imodel != BL_RESULTANT)
        return fail(L, "interface: field 'mu_t' goes with the resultant model (model = "
                       "\"resultant\" here or in model{ interface = \"resultant\" })");
    if (m->dim == 3 && field(L, 2, "points")) {
        int n = lua_istable(L, -1) ? (int)lua_rawlen(L, -1) : 0;
        if (n < 3 || n > BL_JOINT_POINTS)
            return fail(L, "interface: field 'points' must list 3 to %d points {x, y, z}, the "
                           "corners of a convex polygon in order, got %s", BL_JOINT_POINTS,
                        lua_istable(L, -1) ? lua_pushfstring(L, "%d", n) : luaL_typename(L, -1));
        for (int i = 0; i < n; i++) {
            char what[48];
            snprintf(what, sizeof what, "field 'points' point %d", i + 1);
            lua_geti(L, -1, i + 1);
            s.p3[i] = to_point3(L, "interface", what);
        }
        lua_pop(L, 1);
        double tol, gap, area;
        bl_vec3 nrm;
        bl_contact_tolerances(m, &tol, &gap);
        for (int i = 1; i < n; i++)
            for (int j = 0; j < i; j++)
                if (bl_v3_norm(bl_v3_sub(s.p3[i], s.p3[j])) <= tol)
                    return fail(L, "interface: field 'points' point %d repeats point %d (within tol = %.3g); "
                                   "give each corner once", i + 1, j + 1, tol);
        int r = bl_polygon3_check(s.p3, n, tol, &nrm, &area);
        if (r == -1) return fail(L, "interface: field 'points' encloses no area (on a line?)");
        if (r == -2) return fail(L, "interface: field 'points' is not a convex polygon in order");
        if (r == -3) { /* no one corner to blame: how far from the plane of
                        * points 1, 2 and the first off their line the
                        * farthest is */
            bl_vec3 u = bl_v3_sub(s.p3[1], s.p3[0]), w = {0, 0, 0};
            int third = 2;
            for (; third < n; third++) {
                w = bl_v3_cross(u, bl_v3_sub(s.p3[third], s.p3[0]));
                if (bl_v3_norm(w) > tol * bl_v3_norm(u)) break;
            }
            int far = 0;
            double off = 0.0;
            for (int i = 0; third < n && i < n; i++) {
                double d = fabs(bl_v3_dot(bl_v3_sub(s.p3[i], s.p3[0]), w)) / bl_v3_norm(w);
                if (d > off) off = d, far = i;
            }
            return fail(L, "interface: field 'points' do not lie in one plane: the plane through "
                           "points 1, 2 and %d misses point %d by %.3g (tol = %.3g)",
                        third + 1, far + 1, off, tol);
        }
        if (r < 0)
            return fail(L, "interface: field 'points' point %d lies off the polygon's plane "
                           "(by more than tol = %.3g)", -r - 3, tol);
        s.npoints = n;
    } else if (field(L, 2, "points")) {
        if (!lua_istable(L, -1) || lua_rawlen(L, -1) != 2)
            return fail(L, "interface: field 'points' must be two points {{x1, y1}, {x2, y2}}");
        for (int i = 0; i < 2; i++) {
            lua_geti(L, -1, i + 1);
            s.p[i] = to_point(L, "interface", i ? "field 'points' point 2" : "field 'points' point 1");
        }
        lua_pop(L, 1);
        if (bl_v2_norm(bl_v2_sub(s.p[1], s.p[0])) == 0)
            return fail(L, "interface: field 'points' has two equal points");
        s.npoints = 2;
    }
    if (!s.npoints && !s.has_mu && !s.has_cohesion && !s.has_imodel && !s.has_mu_t)
        return fail(L, m->dim == 3 ? "interface: give 'mu', 'cohesion', 'model', 'mu_t' or 'points'"
                                   : "interface: give 'mu', 'cohesion' or 'points'");
    bl_error err;
    if (bl_joint_check(m, &s, &err)) return fail(L, "%s", err.msg);
    if (!s.npoints) { /* an override needs an interface to act on: check now */
        if (!m->contacts_valid && bl_contact_detect(m, &err)) return fail_in(L, "interface", err.msg);
        int found = 0;
        for (int k = 0; k < m->ninterfaces && !found; k++) {
            const bl_interface *in = &m->interfaces[k];
            found = (in->a == s.a && in->b == s.b) || (in->a == s.b && in->b == s.a);
        }
        if (!found)
            return fail(L, "interface: blocks %d and %d share no interface to change; "
                           "give points = {{x1, y1}, {x2, y2}} to declare one", s.a + 1, s.b + 1);
    }
    if (bl_model_add_joint(m, &s, &err)) return fail(L, "%s", err.msg);
    return 0;
}

/* Field 'weight' of the point-load table at t (load dead or live, k):
 * a carried weight, dead, given alone; 0 when absent. */
static double weight_field(lua_State *L, int t, const char *fn, int k)
{
    if (!field_given(L, t, "weight")) return 0.0;
    if (k)
        fail(L, "%s: field 'weight' is for dead loads (a carried weight is dead; the weight-proportional "
                "live load acts on it by itself)", fn);
    if (field_given(L, t, "force") || field_given(L, t, "moment"))
        fail(L, "%s: give field 'weight' alone (a carried weight acts along gravity), or 'force' and "
                "'moment'", fn);
    return number_field(L, t, fn, "weight", 0.0, POSITIVE);
}

/* What load{} asked, applied (2D and 3D alike): kinds[0] and kinds[1] are
 * the dead and live choices (0 self weight / horizontal, 1 none, 2 the
 * point load in pl, -1 not given). */
static void apply_loads(lua_State *L, bl_model *m, const int kinds[2], const bl_point_load pl[2])
{
    bl_error err;
    for (int k = 0; k < 2; k++) /* both checked before either is added */
        if (kinds[k] == 2 && bl_model_check_point_load(m, &pl[k], &err)) fail(L, "%s", err.msg);
    for (int k = 0; k < 2; k++)
        if (kinds[k] == 2 && bl_model_add_point_load(m, &pl[k], &err)) fail(L, "%s", err.msg);
    if (kinds[0] == 0) m->self_weight = 1;
    if (kinds[0] == 1 || kinds[1] == 1) {
        int live = kinds[1] == 1, n = 0;
        if (live) m->live_weight = 0;
        else m->self_weight = 0;
        for (int i = 0; i < m->nloads; i++)
            if (m->loads[i].live != live) m->loads[n++] = m->loads[i];
        m->nloads = n;
    }
    if (kinds[1] == 0) m->live_weight = 1;
}

/* load{} in a 3D model: the self weight along gravity; a live load
 * proportional to weight along a horizontal {dx, dy} or any {dx, dy, dz}
 * direction; point loads { block, at = {x, y, z}, force = {fx, fy, fz},
 * moment = {mx, my, mz} } (a force, a couple, or both), dead or live, or
 * a carried weight { block, at, weight } (dead; its 'at' may lie outside
 * the block). */
static int load_3d(lua_State *L, bl_model *m)
{
    static const char *const point_fields[] = {"block", "at", "force", "moment", "weight", NULL};
    static const char *const dead_choices[] = {"self-weight", "none", NULL};
    static const char *const live_choices[] = {"horizontal", "none", NULL};
    double tilt = number_field(L, 2, "load", "tilt", NAN, ANY);
    if (!isnan(tilt) && !(fabs(tilt) < 90))
        return fail(L, "load: field 'tilt' must be an angle in degrees between -90 and 90");
    bl_vec2 axis = m->tilt_axis;
    if (point_field(L, 2, "load", "axis", &axis)) {
        if (isnan(tilt)) return fail(L, "load: field 'axis' goes with 'tilt'");
        if (bl_v2_norm(axis) == 0)
            return fail(L, "load: field 'axis' must be a non-zero horizontal direction {x, y}");
    }
    int kinds[2] = {-1, -1};
    bl_point_load pl[2] = {{0}, {0}};
    for (int k = 0; k < 2; k++) {
        const char *f = k ? "live" : "dead";
        if (!field(L, 2, f)) continue;
        if (!lua_istable(L, -1)) {
            lua_pop(L, 1);
            kinds[k] = load_choice(L, k, k ? live_choices : dead_choices);
            continue;
        }
        char fn[32];
        snprintf(fn, sizeof fn, "load %s", f);
        int t = lua_gettop(L);
        check_fields(L, t, fn, point_fields, 0);
        if (!field(L, t, "block")) fail(L, "%s: field 'block' is missing", fn);
        pl[k].block = block_index(L, m, -1, fn, "field 'block'");
        lua_pop(L, 1);
        if (m->blocks[pl[k].block].support)
            fail(L, "%s: block %d is a support; loads on it do nothing", fn, pl[k].block + 1);
        pl[k].weight = weight_field(L, t, fn, k);
        int has_force = field_given(L, t, "force"), has_moment = field_given(L, t, "moment");
        if (!has_force && !has_moment && !pl[k].weight)
            fail(L, "%s: give field 'force' {fx, fy, fz} (at 'at'), 'moment' {mx, my, mz}, or both; or "
                    "'weight'", fn);
        pl[k].at3 = m->blocks[pl[k].block].centroid3;
        if (field(L, t, "at")) {
            pl[k].at3 = to_point3(L, fn, "field 'at'");
            const bl_block *bk = &m->blocks[pl[k].block];
            const double *b = bk->box3;
            double tol = 1e-9 * hypot(hypot(b[3] - b[0], b[4] - b[1]), b[5] - b[2]);
            if (!pl[k].weight && bl_polyhedron_depth(&bk->solid, pl[k].at3) < -tol)
                fail(L, "%s: field 'at' (%.9g, %.9g, %.9g) is outside block %d", fn, pl[k].at3.x,
                     pl[k].at3.y, pl[k].at3.z, pl[k].block + 1);
        }
        if (field(L, t, "force")) pl[k].force3 = to_point3(L, fn, "field 'force'");
        if (field(L, t, "moment")) pl[k].moment3 = to_point3(L, fn, "field 'moment'");
        if (!pl[k].weight && bl_v3_norm(pl[k].force3) == 0 && bl_v3_norm(pl[k].moment3) == 0)
            fail(L, "%s: fields 'force' and 'moment' are zero", fn);
        pl[k].live = k;
        kinds[k] = 2;
        lua_pop(L, 1);
    }
    bl_vec3 dir = m->live_dir3;
    if (field(L, 2, "direction")) {
        if (kinds[1] != 0 && !(kinds[1] == -1 && m->live_weight))
            fail(L, "load: field 'direction' goes with live = \"horizontal\"");
        if (lua_istable(L, -1) && lua_rawlen(L, -1) == 2) {
            bl_vec2 d = to_point(L, "load", "field 'direction'");
            dir = bl_v3(d.x, d.y, 0.0);
        } else {
            dir = to_point3(L, "load", "field 'direction'");
        }
        dir = bl_v3_unit(dir);
        if (bl_v3_norm(dir) == 0) fail(L, "load: field 'direction' must be a non-zero vector");
    }
    apply_loads(L, m, kinds, pl);
    if (kinds[1] == 0 || field_given(L, 2, "direction")) m->live_dir3 = dir;
    if (!isnan(tilt)) {
        m->tilt = tilt * M_PI / 180.0;
        m->tilt_axis = bl_v2_unit(axis);
    }
    return 0;
}

static int model_load(lua_State *L)
{
    static const char *const fields[] = {"dead", "live", "direction", "tilt", "axis", NULL};
    static const char *const point_fields[] = {"block", "at", "force", "moment", "weight", NULL};
    static const char *const dead_choices[] = {"self-weight", "none", NULL};
    static const char *const live_choices[] = {"horizontal", "none", NULL};
    bl_model *m = check_model(L, 1);
    one_table(L, "load");
    check_fields(L, 2, "load", fields, 0);
    lua_pushnil(L);
    if (!lua_next(L, 2)) return fail(L, "load: an empty table changes nothing: give dead, live, or tilt");
    lua_pop(L, 2);
    if (m->dim == 3) return load_3d(L, m);
    int kinds[2] = {-1, -1}; /* dead, live: choice index, 2 = point load, -1 = absent */
    bl_point_load pl[2] = {{0}, {0}};
    for (int k = 0; k < 2; k++) {
        const char *f = k ? "live" : "dead";
        if (!field(L, 2, f)) continue;
        if (lua_istable(L, -1)) {
            char fn[32];
            snprintf(fn, sizeof fn, "load %s", f);
            int t = lua_gettop(L);
            check_fields(L, t, fn, point_fields, 0);
            if (!field(L, t, "block")) fail(L, "%s: field 'block' is missing", fn);
            pl[k].block = block_index(L, m, -1, fn, "field 'block'");
            lua_pop(L, 1);
            if (m->blocks[pl[k].block].support)
                fail(L, "%s: block %d is a support; loads on it do nothing", fn,
                           pl[k].block + 1);
            pl[k].weight = weight_field(L, t, fn, k);
            pl[k].moment = number_field(L, t, fn, "moment", 0.0, ANY);
            if (!field_given(L, t, "force") && !field_given(L, t, "moment") && !pl[k].weight)
                fail(L, "%s: give field 'force' {fx, fy} (at 'at'), 'moment' m (a couple, counter-clockwise), "
                     "or both; or 'weight'", fn);
            const bl_block *bk = &m->blocks[pl[k].block];
            pl[k].at = bk->centroid;
            if (point_field(L, t, fn, "at", &pl[k].at)) {
                double tol = 1e-9 * hypot(bk->box[2] - bk->box[0], bk->box[3] - bk->box[1]);
                if (!pl[k].weight && bl_polygon_depth(bk->v, bk->nv, pl[k].at) < -tol)
                    fail(L, "%s: field 'at' (%.9g, %.9g) is outside block %d", fn, pl[k].at.x, pl[k].at.y,
                         pl[k].block + 1);
            }
            point_field(L, t, fn, "force", &pl[k].force);
            if (!pl[k].weight && bl_v2_norm(pl[k].force) == 0 && pl[k].moment == 0)
                fail(L, "%s: fields 'force' and 'moment' are zero", fn);
            pl[k].live = k;
            kinds[k] = 2;
            lua_pop(L, 1);
        } else {
            lua_pop(L, 1);
            kinds[k] = load_choice(L, k, k ? live_choices : dead_choices);
        }
    }
    bl_vec2 dir = m->live_dir;
    int has_dir = point_field(L, 2, "load", "direction", &dir);
    if (has_dir && bl_v2_norm(dir) == 0)
        return fail(L, "load: field 'direction' must be a non-zero vector");
    if (has_dir && kinds[1] != 0 && !(kinds[1] == -1 && m->live_weight))
        return fail(L, "load: field 'direction' goes with live = \"horizontal\"");
    double tilt = number_field(L, 2, "load", "tilt", NAN, ANY);
    if (!isnan(tilt) && !(fabs(tilt) < 90))
        return fail(L, "load: field 'tilt' must be an angle in degrees between -90 and 90");
    if (field_given(L, 2, "axis")) return fail(L, "load: field 'axis' is for 3D models");

    apply_loads(L, m, kinds, pl);
    if (has_dir) m->live_dir = bl_v2_unit(dir);
    if (!isnan(tilt)) m->tilt = tilt * M_PI / 180.0;
    return 0;
}

static int model_stats(lua_State *L)
{
    bl_model *m = check_model(L, 1);
    if (lua_gettop(L) > 1) return fail(L, "stats: takes no arguments, got %d", lua_gettop(L) - 1);
    bl_error err;
    /* a model without blocks has nothing to detect: its counts are 0 */
    if (m->nblocks > 0 && !m->contacts_valid && bl_contact_detect(m, &err))
        return fail_in(L, "stats", err.msg);
    int nfree = bl_model_free_blocks(m);
    double tol, gap;
    bl_contact_tolerances(m, &tol, &gap);
    lua_createtable(L, 0, 6);
    set_integer(L, "blocks", nfree);
    set_integer(L, "supports", m->nblocks - nfree);
    set_integer(L, "interfaces", m->ninterfaces);
    set_number(L, "size", bl_model_size(m));
    set_number(L, "tol", tol);
    set_number(L, "gap", gap);
    set_integer(L, "dim", m->dim);
    return 1;
}

/* A new table with what an interface is: its blocks a and b, mu, its
 * points (2D: the two ends; 3D: the contact polygon), its normal and (3D)
 * its interface model. */
static void push_interface(lua_State *L, const bl_model *m, const bl_interface *in)
{
    lua_createtable(L, 0, 10);
    set_integer(L, "a", in->a + 1);
    set_integer(L, "b", in->b + 1);
    set_number(L, "mu", in->mu);
    int n = m->dim == 3 ? in->np : 2;
    lua_createtable(L, n, 0);
    for (int i = 0; i < n; i++) {
        if (m->dim == 3) push_triple(L, in->poly[i]);
        else push_point(L, in->p[i]);
        lua_rawseti(L, -2, i + 1);
    }
    lua_setfield(L, -2, "points");
    if (m->dim == 3) push_triple(L, in->n3);
    else push_point(L, in->normal);
    lua_setfield(L, -2, "normal");
    if (m->dim == 3) set_string(L, "model", in->imodel == BL_RESULTANT ? "resultant" : "vertex");
    if (m->dim == 3 && in->imodel == BL_RESULTANT) set_number(L, "mu_t", bl_interface_torsion(in));
}

/* model:interface_info(k) -> { a, b, normal, points, mu, cohesion, area } of
 * detected interface k (detecting first when needed). */
static int model_interface_info(lua_State *L)
{
    bl_model *m = check_model(L, 1);
    bl_error err;
    if (!m->contacts_valid && bl_contact_detect(m, &err)) return fail_in(L, "interface_info", err.msg);
    int whole = 0;
    lua_Integer k = lua_type(L, 2) == LUA_TNUMBER ? lua_tointegerx(L, 2, &whole) : 0;
    if (!whole)
        return fail(L, "interface_info: argument 1 must be an interface number, got %s",
                    lua_type(L, 2) == LUA_TNUMBER ? "a fraction" : luaL_typename(L, 2));
    if (k < 1 || k > m->ninterfaces)
        return fail(L, "interface_info: argument 1 must be an interface number from 1 to %d, "
                       "got %lld", m->ninterfaces, (long long)k);
    const bl_interface *in = &m->interfaces[k - 1];
    push_interface(L, m, in);
    set_number(L, "cohesion", in->cohesion);
    if (m->dim == 3) set_number(L, "area", in->area3);
    else set_number(L, "length", bl_v2_norm(bl_v2_sub(in->p[1], in->p[0])));
    return 1;
}

/* model:dim() -> 2 or 3 */
static int model_dim(lua_State *L)
{
    lua_pushinteger(L, check_model(L, 1)->dim);
    return 1;
}

/* model:block_info(i) -> { vertices, faces (3D), centroid, area and
 * thickness (2D) or volume (3D), weight, support } */
static int model_block_info(lua_State *L)
{
    bl_model *m = check_model(L, 1);
    const bl_block *b = &m->blocks[block_index(L, m, 2, "block_info", "argument 1")];
    if (m->dim == 3) {
        const bl_polyhedron *p = &b->solid;
        lua_createtable(L, 0, 6);
        lua_createtable(L, p->nv, 0);
        for (int i = 0; i < p->nv; i++) {
            push_triple(L, p->v[i]);
            lua_rawseti(L, -2, i + 1);
        }
        lua_setfield(L, -2, "vertices");
        lua_createtable(L, p->nf, 0);
        for (int k = 0; k < p->nf; k++) {
            lua_createtable(L, p->fs[k + 1] - p->fs[k], 0);
            for (int t = p->fs[k]; t < p->fs[k + 1]; t++) {
                lua_pushinteger(L, p->fi[t] + 1);
                lua_rawseti(L, -2, t - p->fs[k] + 1);
            }
            lua_rawseti(L, -2, k + 1);
        }
        lua_setfield(L, -2, "faces");
        push_triple(L, b->centroid3);
        lua_setfield(L, -2, "centroid");
        set_number(L, "volume", b->volume);
        set_number(L, "weight", b->weight);
        set_boolean(L, "support", b->support);
        return 1;
    }
    lua_createtable(L, 0, 6);
    lua_createtable(L, b->nv, 0);
    for (int i = 0; i < b->nv; i++) {
        push_point(L, b->v[i]);
        lua_rawseti(L, -2, i + 1);
    }
    lua_setfield(L, -2, "vertices");
    push_point(L, b->centroid);
    lua_setfield(L, -2, "centroid");
    set_number(L, "area", b->area);
    set_number(L, "thickness", b->thickness);
    set_number(L, "weight", b->weight);
    set_boolean(L, "support", b->support);
    return 1;
}

/* ---- solve and results ---------------------------------------------------- */




static void push_details(lua_State *L, const bl_solution *s);

/* A table of the residuals (the flow rule's where they were checked). */
static void push_residuals(lua_State *L, const bl_residuals *r)
{
    lua_createtable(L, 0, 8);
    set_number(L, "equilibrium", r->equilibrium);
    set_number(L, "yield", r->yield);
    set_number(L, "admissibility", r->admissibility);
    set_number(L, "complementarity", r->complementarity);
    set_number(L, "normalization", r->normalization);
    set_number(L, "work", r->work);
    if (!isnan(r->flow)) {
        set_number(L, "flow", r->flow);
        set_number(L, "dilatancy", r->dilatancy);
    }
}

/* Into the table on the top, where the solve was given mechanisms to try
 * (solve{ mechanisms }): how many were tried and how many certified. */
static void set_mechanisms_given(lua_State *L, const bl_solution *s)
{
    if (!s->given_tried) return;
    lua_createtable(L, 0, 2);
    set_integer(L, "tried", s->given_tried);
    set_integer(L, "certified", s->given_certified);
    lua_setfield(L, -2, "mechanisms_given");
}

/* Into the result table on the top: each loaded interface's centre of
 * pressure (`at`, on the thrust line) and the reactions on the supports. */
static void push_thrust(lua_State *L, const bl_solution *s)
{
    const bl_model *m = s->model;
    size_t ni = (size_t)m->ninterfaces + 1, nb = (size_t)m->nblocks + 1;
    /* scratch, owned by Lua (an error cannot leak it) */
    bl_vec3 *F = lua_newuserdatauv(L, (2 * ni + 2 * nb) * sizeof *F + ni * sizeof(double), 0);
    bl_vec3 *C = F + ni, *R = C + ni, *M = R + nb;
    double *N = (double *)(M + nb);
    bl_solution_resultants(s, F, N, C);
    bl_solution_reactions(s, R, M);
    lua_createtable(L, 0, 4);
    for (int i = 0; i < m->nblocks; i++) {
        if (!m->blocks[i].support) continue;
        lua_createtable(L, 0, 2);
        if (m->dim == 3) push_triple(L, R[i]);
        else push_pair(L, R[i].x, R[i].y);
        lua_setfield(L, -2, "force");
        if (m->dim == 3) {
            push_triple(L, M[i]);
            lua_setfield(L, -2, "moment");
        } else {
            set_number(L, "moment", M[i].z);
        }
        lua_rawseti(L, -2, i + 1);
    }
    lua_setfield(L, -3, "reactions");
    lua_getfield(L, -2, "interfaces");
    for (int k = 0; k < m->ninterfaces; k++) {
        if (!(N[k] > 0.0)) continue;
        lua_rawgeti(L, -1, k + 1);
        if (m->dim == 3) push_triple(L, C[k]);
        else push_pair(L, C[k].x, C[k].y);
        lua_setfield(L, -2, "at");
        lua_pop(L, 1);
    }
    lua_pop(L, 2);
}

/* Builds the result table of doc/guide.md from s (on the stack at sidx);
 * dead: s is the dead-load check's r.dead, whose live load is the dead one
 * (no participating mass: no acceleration loads it). */
static void push_result(lua_State *L, const bl_solution *s, int sidx, int dead)
{
    const bl_model *m = s->model;
    lua_createtable(L, 0, 20);
    lua_pushvalue(L, sidx);
    lua_setfield(L, -2, "_solution");
    set_number(L, "alpha", s->alpha);
    set_string(L, "status", bl_status_name(s->status));
    set_string(L, "message", bl_status_sentence(s->status));
    set_boolean(L, "verified", s->verified);
    if (s->stands >= 0) set_boolean(L, "stands", s->stands);
    if (!isnan(s->alpha_min)) set_number(L, "alpha_min", s->alpha_min);
    set_string(L, "method", s->method);
    set_string(L, "flow", s->flow);
    set_integer(L, "dim", m->dim);
    for (int k = 0; k < m->ninterfaces; k++)
        if (isinf(m->interfaces[k].mu)) {
            set_boolean(L, "rigid_joints", 1); /* some joint has mu = inf */
            break;
        }
    int seq = strcmp(s->method, "seqlp") == 0, ipopt = strcmp(s->method, "mpec") == 0;
    if (seq || (ipopt && strcmp(s->flow, "nonassociative") == 0)) {
        set_number(L, "alpha_assoc", s->alpha_assoc);
        set_boolean(L, "assoc_verified", s->assoc_verified);
    }
    if (seq || ipopt) {
        set_boolean(L, "certified", s->certified);
        set_boolean(L, "interrupted", s->interrupted);
        set_boolean(L, "time_up", s->time_up);
    }
    if (seq) {
        set_number(L, "alpha_rigid", s->alpha_rigid);
        if (s->certified) {
            set_number(L, "alpha_settled", s->alpha_settled);
            set_boolean(L, "certified_early", s->early);
            if (s->given) set_integer(L, "from_mechanism", s->given);
        }
        set_boolean(L, "assoc_is_solution", s->assoc_is_solution);
        set_mechanisms_given(L, s);
        if (s->restarts_why) set_string(L, "restarts_why", s->restarts_why);
        set_integer(L, "skipped", s->skipped);
        if (s->lp_switched) set_boolean(L, "lp_switched", 1);
        if (s->live_scales_dead) set_boolean(L, "live_scales_dead", 1);
        if (s->none_dilates) set_boolean(L, "none_dilates", 1);
        set_integer(L, "lps", s->lps);
        set_number(L, "slip", s->slip);
        if (s->path_steps > 0) {
            lua_createtable(L, 0, 5);
            set_boolean(L, "taken", s->path_taken);
            set_boolean(L, "stopped", s->path_stopped);
            set_integer(L, "steps", s->path_steps);
            set_number(L, "alpha", s->path_alpha);
            set_number(L, "products", s->path_products);
            set_number(L, "time", s->path_seconds);
            lua_setfield(L, -2, "path");
        }
        /* history[k] = the alphas of start k, from the alpha it began at;
         * starts[k] = what start k cost and what it certified */
        lua_createtable(L, s->nstarts, 0);
        for (int k = 0; k < s->nstarts; k++) {
            int first = s->start[k].first;
            int end = k + 1 < s->nstarts ? s->start[k + 1].first : s->nhistory;
            lua_createtable(L, end - first, 0);
            for (int i = first; i < end; i++) {
                lua_pushnumber(L, s->history[i]);
                lua_rawseti(L, -2, i - first + 1);
            }
            lua_rawseti(L, -2, k + 1);
        }
        lua_setfield(L, -2, "history");
        lua_createtable(L, s->nstarts, 0);
        for (int k = 0; k < s->nstarts; k++) {
            const bl_start *st = &s->start[k];
            lua_createtable(L, 0, 7);
            set_integer(L, "lps", st->lps);
            set_integer(L, "certificates", st->certificates);
            set_integer(L, "nearest", st->nearest);
            set_integer(L, "iterations", st->iterations);
            set_number(L, "time", st->seconds);
            set_boolean(L, "certified", st->alpha == st->alpha);
            if (st->alpha == st->alpha) set_number(L, "alpha", st->alpha);
            if (st->continues) set_integer(L, "continues", st->continues);
            if (isfinite(st->search_mu)) set_number(L, "search_mu", st->search_mu);
            lua_rawseti(L, -2, k + 1);
        }
        lua_setfield(L, -2, "starts");
        if (s->note[0]) {
            lua_pushstring(L, s->note);
            lua_setfield(L, -2, "note");
        }
    }
    if (ipopt) {
        lua_createtable(L, 0, 7);
        set_string(L, "status", s->nlp_status);
        set_string(L, "complementarity", s->comp);
        set_string(L, "start", s->start_kind);
        if (s->start_why) set_string(L, "start_why", s->start_why);
        set_number(L, "alpha_start", s->alpha_start);
        set_number(L, "pairs", s->pair_sum);
        set_number(L, "alpha", s->alpha_ipopt);
        set_boolean(L, "kept_start", s->kept_start);
        if (s->kept_start) { /* (else they are the answer's) */
            push_residuals(L, &s->res_ipopt);
            lua_setfield(L, -2, "residuals");
        }
        if (s->given) set_integer(L, "start_mechanism", s->given); /* the start's answer: seqlp's from_mechanism */
        set_mechanisms_given(L, s);
        lua_setfield(L, -2, "ipopt");
        if (strcmp(s->flow, "nonassociative") == 0) set_number(L, "slip", s->slip);
    }
    if (m->dim == 3 && s->cone_rounds > 0) {
        lua_createtable(L, 0, 3);
        set_integer(L, "facets", s->cone.facets);
        set_string(L, "kind", s->cone.adaptive ? "adaptive"
                              : s->cone.circumscribed ? "circumscribed" : "inscribed");
        set_integer(L, "rounds", s->cone_rounds);
        lua_setfield(L, -2, "cone");
    }
    set_string(L, "lp", s->lp ? s->lp : "");
    set_integer(L, "iterations", s->iterations);
    set_number(L, "tolerance", s->tolerance);
    int nfree = bl_model_free_blocks(m);
    lua_createtable(L, 0, 5);
    set_integer(L, "blocks", nfree);
    set_integer(L, "supports", m->nblocks - nfree);
    set_integer(L, "interfaces", m->ninterfaces);
    set_integer(L, "rows", s->rows);
    set_integer(L, "columns", s->cols);
    set_number(L, "factor_nnz", s->factor_nnz);
    lua_setfield(L, -2, "size");

    lua_createtable(L, 0, 6);
    set_number(L, "detection", s->time.detection);
    set_number(L, "assembly", s->time.assembly);
    set_number(L, "solve", s->time.solve);
    set_number(L, "verification", s->time.verification);
    set_number(L, "stands", s->time.stands);
    set_number(L, "total", s->time.total);
    lua_setfield(L, -2, "timings");

    if (!s->has_mechanism) return;
    push_residuals(L, &s->res);
    lua_setfield(L, -2, "residuals");
    if (!isnan(s->res.below)) { /* not residuals: the motions either side of the slip threshold */
        lua_createtable(L, 0, 2);
        set_number(L, "below", s->res.below);
        set_number(L, "above", s->res.above);
        lua_setfield(L, -2, "motion_gap");
    }
    if (!bl_solution_moves(s)) return; /* Ipopt's last point, no answer: its residuals only */

    push_details(L, s);
    lua_setfield(L, -3, "interfaces");
    lua_setfield(L, -2, "mechanism");
    int count[4] = {0};
    for (int k = 0; k < m->ninterfaces; k++) count[s->state[k]]++;
    lua_createtable(L, 0, 4);
    for (int st = 0; st < 4; st++) {
        lua_pushinteger(L, count[st]);
        lua_setfield(L, -2, bl_state_name((bl_state)st));
    }
    lua_setfield(L, -2, "states");
    bl_participation pp;
    if (!dead && bl_solution_participation(s, &pp) == 0) {
        lua_createtable(L, 0, 6);
        set_number(L, "chain", pp.chain);
        set_integer(L, "blocks", pp.blocks);
        set_integer(L, "bodies", pp.bodies);
        set_integer(L, "groups", pp.groups);
        set_number(L, "participating", pp.participating);
        set_number(L, "ratio", pp.ratio);
        set_number(L, "acceleration", pp.acceleration);
        lua_setfield(L, -2, "participation");
    }
    push_thrust(L, s);
}

/* Pushes a result's mechanism (per block: vx, vy, omega in 2D; vx, vy, vz,
 * wx, wy, wz in 3D) and interfaces tables: blocks, state, geometry, and
 * the forces (2D: n and t at both ends, a hinge; 3D: the contact polygon,
 * its normal and frame, the force (n, t2, t3) at every vertex) with their
 * sums N and T (3D: the shear's magnitude). */
static void push_details(lua_State *L, const bl_solution *s)
{
    const bl_model *m = s->model;
    int nu = m->dim == 3 ? 6 : 3;
    lua_createtable(L, m->nblocks, 0);
    for (int i = 0; i < m->nblocks; i++) {
        lua_createtable(L, nu, 0);
        for (int c = 0; c < nu; c++) {
            lua_pushnumber(L, s->u[nu * i + c]);
            lua_rawseti(L, -2, c + 1);
        }
        lua_rawseti(L, -2, i + 1);
    }

    lua_createtable(L, m->ninterfaces, 0);
    const double *f = s->force;
    for (int k = 0; k < m->ninterfaces; k++) {
        const bl_interface *in = &m->interfaces[k];
        push_interface(L, m, in);
        set_string(L, "state", bl_state_name(s->state[k]));
        set_number(L, "motion", s->speed_max > 0.0 ? s->speed[k] / s->speed_max : 0.0);
        if (m->dim == 3) {
            push_triple(L, in->t2);
            lua_setfield(L, -2, "t2");
            double N = 0.0, T2 = 0.0, T3 = 0.0;
            lua_createtable(L, in->np, 0);
            for (int e = 0; e < in->np; e++, f += 3) {
                push_triple(L, bl_v3(f[0], f[1], f[2]));
                lua_rawseti(L, -2, e + 1);
                N += f[0];
                T2 += f[1];
                T3 += f[2];
            }
            lua_setfield(L, -2, "forces");
            set_number(L, "N", N);
            set_number(L, "T", hypot(T2, T3));
        } else {
            if (s->hinge[k] >= 0) {
                push_point(L, in->p[s->hinge[k]]);
                lua_setfield(L, -2, "hinge");
            }
            push_pair(L, f[0], f[2]);
            lua_setfield(L, -2, "n");
            push_pair(L, f[1], f[3]);
            lua_setfield(L, -2, "t");
            set_number(L, "N", f[0] + f[2]);
            set_number(L, "T", f[1] + f[3]);
            f += 4;
        }
        lua_rawseti(L, -2, k + 1);
    }
}

/* Ctrl-C during a solve: the core polls the flag; the handler that was in
 * place (the prompt's, or lua.c's under a stock interpreter) runs too. */
static struct sigaction previous_sigint;

static void on_sigint(int sig)
{
    bl_interrupt_request();
    if (previous_sigint.sa_handler != SIG_DFL && previous_sigint.sa_handler != SIG_IGN)
        previous_sigint.sa_handler(sig);
}

/* Raises the error of a solve stopped by Ctrl-C, its message ending with
 * the caller's note (compare{} names its row), and leaves that message in
 * the registry (BL_LUA_INTERRUPTED). */
static int interrupted(lua_State *L, const char *note, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static int interrupted(lua_State *L, const char *note, const char *fmt, ...)
{
    char msg[1200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (*note) lua_pushfstring(L, "%s (%s)", msg, note);
    else lua_pushstring(L, msg);
    lua_pushvalue(L, -1);
    lua_setfield(L, LUA_REGISTRYINDEX, BL_LUA_INTERRUPTED);
    return lua_error(L);
}

/* solve{ mechanisms = { r1, r2, ... } }, its value on top: results of
 * models with the blocks of m (as many, the same ones supports), whose
 * mechanisms the sequence tries as certificates (seqlp.h).  Their
 * velocities are copied into a userdata left on the stack above the list. */
static void mechanisms_field(lua_State *L, bl_model *m, bl_seqlp_options *so)
{
    int list = lua_gettop(L);
    if (!lua_istable(L, list))
        fail(L, "solve: field 'mechanisms' must be a list of results, got %s", luaL_typename(L, list));
    if (lua_getfield(L, list, "_solution") != LUA_TNIL)
        fail(L, "solve: field 'mechanisms' must be a list of results, got one result: write { r }");
    lua_pop(L, 1);
    int n = (int)luaL_len(L, list);
    if (n < 1 || n > 1000)
        fail(L, "solve: field 'mechanisms' must list from 1 to 1000 results, got %d", n);
    size_t per = (size_t)(m->dim == 3 ? 6 : 3) * (size_t)m->nblocks; /* each copied: a list's
                                         entries need not outlive the solve */
    double *u = lua_newuserdatauv(L, (size_t)n * per * sizeof *u, 0);
    for (int k = 0; k < n; k++) {
        lua_geti(L, list, k + 1);
        bl_solution **box = NULL;
        if (lua_istable(L, -1) && lua_getfield(L, -1, "_solution") == LUA_TUSERDATA)
            box = luaL_testudata(L, -1, SOLUTION_MT);
        const bl_solution *r = box ? *box : NULL;
        if (!r) fail(L, "solve: field 'mechanisms' entry %d must be a result of solve{}", k + 1);
        if (!bl_solution_moves(r))
            fail(L, "solve: field 'mechanisms' entry %d has no mechanism (its status: %s)", k + 1,
                 bl_status_name(r->status));
        const bl_model *rm = r->model;
        if (rm->dim != m->dim)
            fail(L, "solve: field 'mechanisms' entry %d is a result of a %dD model, this one is %dD", k + 1,
                 rm->dim, m->dim);
        int same = rm->nblocks == m->nblocks;
        for (int b = 0; same && b < m->nblocks; b++) same = rm->blocks[b].support == m->blocks[b].support;
        if (!same)
            fail(L, "solve: field 'mechanisms' entry %d is a result of a model with other blocks (%d, "
                    "against this model's %d, or other supports): a mechanism is given per block",
                 k + 1, rm->nblocks, m->nblocks);
        memcpy(u + (size_t)k * per, r->u, per * sizeof *u);
        lua_pop(L, 2);
    }
    so->nmechanisms = n;
    so->mechanisms = u;
}

/* m:solve(t[, note]): note, a string, ends the message of an interruption
 * (compare{}'s row).  With check set, only the checks of m and t, which
 * refuse what the solve would (compare{} checks every row first). */
static int solve_or_check(lua_State *L, int check)
{
    static const char *const fields[] = {
        "flow",     "method", "lp",    "tolerance", "time_limit",      "iterations", "verbose",
        "mps",      "beta",   "settle", "slip",     "lps",             "starts",     "seed",
        "progress", "start",  "penalty", "complementarity", "cone",       "threads",
        "lp_tolerance", "nearest", "path", "mechanisms", NULL};
    static const char *const flows[] = {"associative", "nonassociative", NULL};
    static const char *const methods[] = {"assoc", "seqlp", "mpec", NULL};
    static const char *const lps[] = {"auto", "simplex", "ipm", NULL};
    static const char *const comps[] = {"penalty", "relaxation", "homotopy", NULL};
    static const char *const starts_from[] = {"cold", "assoc", "seqlp", NULL};
    enum { ASSOC, SEQLP, MPEC };
    bl_model *m = check_model(L, 1);
    char note[400] = "";
    if (!lua_isnoneornil(L, 3)) snprintf(note, sizeof note, "%s", luaL_checkstring(L, 3));
    lua_settop(L, 2);
    opt_table(L, 2);
    check_fields(L, 2, "solve", fields, 0);
    /* By default, the non-associative answer (the associative one beside
     * it) wherever a joint has finite friction.  assoc and seqlp each solve
     * one flow rule, mpec either. */
    int method = choice_field(L, 2, "solve", "method", methods, SEQLP);
    int flow = choice_field(L, 2, "solve", "flow", flows, method == ASSOC ? 0 : 1);
    if (!field_given(L, 2, "method")) method = flow ? SEQLP : ASSOC;
    if (method != MPEC && method != flow)
        fail(L, "solve: method \"%s\" solves the %s flow rule, not flow = \"%s\"",
             methods[method], flows[method], flows[flow]);
    if (method != MPEC && (field_given(L, 2, "start") || field_given(L, 2, "penalty") ||
                           field_given(L, 2, "complementarity")))
        fail(L, "solve: fields 'start', 'penalty' and 'complementarity' go with method = \"mpec\"");
    if (method == MPEC && !field_given(L, 2, "flow")) {
        /* as solve{}'s own default: the associative flow where no joint
         * has finite friction (its rigid joints, as the direct solve's,
         * cannot slide even where they open: doc/theory.md 6) */
        bl_error err;
        if (!m->contacts_valid && bl_contact_detect(m, &err)) return fail_in(L, "solve", err.msg);
        if (!bl_model_finite_friction(m)) flow = 0;
    }
    bl_mpec_options mo;
    bl_mpec_options_default(&mo);
    mo.nonassociative = flow;
    mo.comp = (bl_mpec_complementarity)choice_field(L, 2, "solve", "complementarity", comps,
                                                    mo.comp);
    /* from the other method's answer of the same flow rule */
    mo.start = (bl_mpec_start)choice_field(L, 2, "solve", "start", starts_from,
                                           flow ? BL_MPEC_START_SEQLP : BL_MPEC_START_ASSOC);
    mo.penalty = number_field(L, 2, "solve", "penalty", mo.penalty, POSITIVE);
    if (mo.comp == BL_MPEC_RELAXATION && field_given(L, 2, "penalty"))
        fail(L, "solve: field 'penalty' goes with complementarity = \"penalty\" or \"homotopy\"; "
                "\"relaxation\" bounds the products instead");
    bl_seqlp_options so;
    bl_seqlp_options_default(&so);
    so.beta = number_field(L, 2, "solve", "beta", so.beta, POSITIVE);
    if (so.beta > 1) fail(L, "solve: field 'beta' must be in (0, 1], got %g", so.beta);
    so.settle = number_field(L, 2, "solve", "settle", so.settle, POSITIVE);
    if (so.settle > 0.1) /* (a relative change of alpha: 2 was taken, and meant nothing) */
        fail(L, "solve: field 'settle' must be in (0, 0.1] (the relative change of alpha between LPs "
                "below which it counts as settled), got %g", so.settle);
    so.slip = number_field(L, 2, "solve", "slip", so.slip, POSITIVE);
    if (so.slip > 1e-2)
        fail(L, "solve: field 'slip' must be in (0, 0.01] (a fraction of the largest motion "
                "below which a motion counts as none), got %g", so.slip);
    double cap = number_field(L, 2, "solve", "lps", so.max_lps, ANY);
    if (cap != floor(cap) || cap < 2 || cap > 1e6)
        fail(L, "solve: field 'lps' must be an integer from 2 to 1000000, got %g", cap);
    so.max_lps = (int)cap;
    double starts = number_field(L, 2, "solve", "starts", -1, NONNEG);
    if (starts != floor(starts) || starts > 1e6 || (starts < 0 && field_given(L, 2, "starts")))
        fail(L, "solve: field 'starts' must be an integer from 0 to 1000000, got %g", starts);
    so.starts = (int)starts;
    double seed = number_field(L, 2, "solve", "seed", 1, NONNEG);
    if (seed != floor(seed) || seed > 9e15)
        fail(L, "solve: field 'seed' must be an integer from 0 to 9e15, got %g", seed);
    so.seed = (unsigned long long)seed;
    double nearest = number_field(L, 2, "solve", "nearest", -1, NONNEG);
    if (nearest != floor(nearest) || nearest > 1e6 || (nearest < 0 && field_given(L, 2, "nearest")))
        fail(L, "solve: field 'nearest' must be an integer from 0 to 1000000, got %g", nearest);
    so.nearest = (int)nearest;
    so.progress = boolean_field(L, 2, "solve", "progress", isatty(STDERR_FILENO));
    so.path = field_given(L, 2, "path") ? boolean_field(L, 2, "solve", "path", 0) : -1;
    so.when_sliding = !field_given(L, 2, "method") && !field_given(L, 2, "flow");
    /* The sequence's settings, which an associative answer never uses (but
     * Ipopt's start from the sequence does), nor Ipopt's cold start, which
     * runs no sequence (slip, last, still judges Ipopt's answer). */
    static const char *const seq[] = {"starts", "seed", "nearest", "path", "beta", "settle", "lps",
                                      "slip", "mechanisms", NULL};
    char seq_given[120] = ""; /* those given, for a default solve that runs no sequence */
    for (int k = 0; seq[k]; k++) {
        if (!field_given(L, 2, seq[k])) continue;
        snprintf(seq_given + strlen(seq_given), sizeof seq_given - strlen(seq_given), "%s%s",
                 seq_given[0] ? ", " : "", seq[k]);
        if (!flow && mo.start != BL_MPEC_START_SEQLP)
            fail(L, "solve: field '%s' goes with flow = \"nonassociative\" (the sequence of LPs)", seq[k]);
        if (method == MPEC && mo.start != BL_MPEC_START_SEQLP && strcmp(seq[k], "slip") != 0)
            fail(L, "solve: field '%s' goes with the sequence of LPs, which start = \"%s\" does not run",
                 seq[k], starts_from[mo.start]);
    }
    if (field(L, 2, "mechanisms")) mechanisms_field(L, m, &so); /* (stays on the stack) */
    int lp = choice_field(L, 2, "solve", "lp", lps, 0);
    bl_solve_options o;
    bl_solve_options_default(&o);
    o.tolerance = number_field(L, 2, "solve", "tolerance", o.tolerance, POSITIVE);
    if (o.tolerance > 1e-2) /* (at 1, alpha = 1.65e-10 passed as W4's associative answer) */
        fail(L, "solve: field 'tolerance' must be at most 0.01 (the largest scaled residual of a "
                "verified answer), got %g", o.tolerance);
    o.verbose = boolean_field(L, 2, "solve", "verbose", 0);
    o.lp = lp == 0 ? BL_LP_AUTO : lp == 1 ? BL_LP_SIMPLEX : BL_LP_IPM;
    if (field(L, 2, "mps")) {
        if (lua_type(L, -1) != LUA_TSTRING)
            fail(L, "solve: field 'mps' must be a file name, got %s", luaL_typename(L, -1));
        o.mps = lua_tostring(L, -1); /* stays on the stack during the solve */
    }
    o.lp_tolerance = number_field(L, 2, "solve", "lp_tolerance", 0, POSITIVE);
    if (o.lp_tolerance > 1e-2)
        fail(L, "solve: field 'lp_tolerance' must be at most 0.01, got %g", o.lp_tolerance);
    double seconds = number_field(L, 2, "solve", "time_limit", 0, POSITIVE);
    o.deadline = seconds > 0 ? bl_clock() + seconds : 0;
    double iters = number_field(L, 2, "solve", "iterations", 0, POSITIVE);
    if (iters != floor(iters) || iters > 1e9)
        fail(L, "solve: field 'iterations' must be an integer from 1 to 1000000000, got %g", iters);
    o.iterations = (int)iters;
    double threads = number_field(L, 2, "solve", "threads", 0, POSITIVE);
    if (threads != floor(threads) || threads > 1024)
        fail(L, "solve: field 'threads' must be an integer from 1 to 1024, got %g", threads);
    o.threads = (int)threads;
    if (field(L, 2, "cone")) {
        static const char *const cone_fields[] = {"facets", "kind", NULL};
        static const char *const kinds[] = {"inscribed", "circumscribed", "adaptive", NULL};
        if (m->dim != 3) fail(L, "solve: field 'cone' is for 3D models");
        if (!lua_istable(L, -1))
            fail(L, "solve: field 'cone' must be a table { facets = 8, kind = \"inscribed\" }");
        int ct = lua_gettop(L);
        check_fields(L, ct, "solve cone", cone_fields, 0);
        double k = number_field(L, ct, "solve cone", "facets", 8, POSITIVE);
        if (k != floor(k) || k < 3 || k > 64)
            fail(L, "solve cone: field 'facets' must be an integer from 3 to 64, got %g", k);
        o.cone.facets = (int)k;
        int kind = choice_field(L, ct, "solve cone", "kind", kinds, 0);
        o.cone.circumscribed = kind == 1;
        o.cone.adaptive = kind == 2;
        lua_pop(L, 1);
    }
    if (method == MPEC && iters > 0) {
        mo.iterations = (int)iters; /* Ipopt's cap; the start's LP keeps its own */
        o.iterations = 0;
    }
    if (m->nblocks == 0)
        fail(L, "solve: the model has no blocks; add them with %s",
             m->dim == 3 ? "box{}, extrude{}, wall{ depth }, dome{} or facade{}" : "block{}, wall{} or arch{}");
    if (check) return 0;

    bl_solution **box = lua_newuserdatauv(L, sizeof *box, 0);
    *box = NULL;
    luaL_setmetatable(L, SOLUTION_MT);
    int sidx = lua_gettop(L);
    bl_solution **dead = lua_newuserdatauv(L, sizeof *dead, 0); /* r.dead, where infeasible */
    *dead = NULL;
    luaL_setmetatable(L, SOLUTION_MT);
    lua_pushvalue(L, sidx); /* the answer's box on top, for push_result */
    lua_remove(L, sidx);
    sidx = lua_gettop(L);
    bl_error err;
    struct sigaction sa, old;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_sigint;
    sigemptyset(&sa.sa_mask);
    bl_interrupt_clear();
    lua_pushnil(L);
    lua_setfield(L, LUA_REGISTRYINDEX, BL_LUA_INTERRUPTED);
    sigaction(SIGINT, &sa, &old);
    previous_sigint = old;
    so.base = o;
    mo.seq = so;
    mo.seq.when_sliding = 0;
    o.progress = so.progress; /* the associative LP's own line */
    int rc = method == MPEC    ? bl_mpec_solve(m, &mo, box, &err)
             : method == SEQLP ? bl_seqlp_solve(m, &so, box, &err)
                               : bl_assoc_solve(m, &o, box, &err);
    /* why no equilibrium: the dead load alone, as r.dead (Ctrl-C stops it
     * too; an error or a stop leaves r.dead out) */
    int dead_load = m->self_weight;
    for (int l = 0; l < m->nloads; l++) dead_load |= !m->loads[l].live;
    bl_error derr;
    if (rc == 0 && (*box)->status == BL_INFEASIBLE && dead_load && !bl_interrupt_pending() &&
        bl_assoc_dead_alone(m, &o, dead, &derr) == 0 && (*dead)->status == BL_INTERRUPTED) {
        bl_solution_free(*dead);
        *dead = NULL;
    }
    sigaction(SIGINT, &old, NULL);
    if (rc) return fail_in(L, "solve", err.msg);
    const bl_solution *s = *box;
    if (s->status == BL_INTERRUPTED && !s->interrupted) {
        /* nothing to keep: last() no longer returns an earlier solve */
        lua_pushnil(L);
        lua_setfield(L, LUA_REGISTRYINDEX, LAST_RESULT);
        return interrupted(L, note, "solve: interrupted (Ctrl-C); the model is as it was");
    }
    push_result(L, s, sidx, 0);
    if (so.when_sliding && seq_given[0] && strcmp(s->method, "assoc") == 0) {
        /* solve's default on a model without finite friction: the
         * associative answer, no sequence to take these fields */
        lua_pushstring(L, seq_given);
        lua_setfield(L, -2, "unused");
    }
    if (*dead) {
        push_result(L, *dead, sidx - 1, 1);
        lua_setfield(L, -2, "dead");
    }
    lua_pushvalue(L, -1);
    lua_setfield(L, LUA_REGISTRYINDEX, LAST_RESULT);
    /* A sequence stopped by Ctrl-C still stops the chunk, but what it found
     * is kept for last(). */
    if (s->interrupted) {
        if (strcmp(s->method, "mpec") == 0)
            return interrupted(L, note, "solve: interrupted (Ctrl-C) in Ipopt; its start's verified "
                                        "alpha, %.6g, is in last()", s->alpha);
        if (s->certified)
            return interrupted(L, note, "solve: interrupted (Ctrl-C) after %d LPs; the lowest "
                                        "certified alpha so far, %.6g, is in last()", s->lps, s->alpha);
        return interrupted(L, note, "solve: interrupted (Ctrl-C) after %d LP%s, nothing certified "
                                    "yet; the history is in last()", s->lps, s->lps == 1 ? "" : "s");
    }
    return 1;
}

static int model_solve(lua_State *L)
{
    return solve_or_check(L, 0);
}

/* core.check_solve(m, t): raises what m:solve(t) would refuse, and solves
 * nothing. */
static int core_check_solve(lua_State *L)
{
    return solve_or_check(L, 1);
}

/* core.last(): the result of the latest solve, also of one stopped by Ctrl-C. */
static int core_last(lua_State *L)
{
    lua_getfield(L, LUA_REGISTRYINDEX, LAST_RESULT);
    return 1;
}

static int solution_gc(lua_State *L)
{
    bl_solution **p = luaL_checkudata(L, 1, SOLUTION_MT);
    bl_solution_free(*p);
    *p = NULL;
    return 0;
}

/* core.draw(solution, file, format, width, azimuth, elevation) */
static int core_draw(lua_State *L)
{
    bl_solution **p = luaL_checkudata(L, 1, SOLUTION_MT);
    const char *file = luaL_checkstring(L, 2);
    const char *fmt = luaL_checkstring(L, 3);
    int width = (int)luaL_optinteger(L, 4, 0);
    bl_view view = {luaL_optnumber(L, 5, BL_VIEW_AZIMUTH), luaL_optnumber(L, 6, BL_VIEW_ELEVATION)};
    if (!lua_isnoneornil(L, 5) && (*p)->model && (*p)->model->dim == 2)
        return fail(L, "%s: field 'view' is for 3D results; a 2D model is drawn in its plane", fmt);
    bl_error err;
    int rc = strcmp(fmt, "svg") == 0 ? bl_draw_svg(*p, file, width, &view, &err)
                                     : bl_draw_png(*p, file, width, &view, &err);
    if (rc) return fail(L, "%s", err.msg);
    return 0;
}

/* core.vtk(solution, file) */
static int core_vtk(lua_State *L)
{
    bl_solution **p = luaL_checkudata(L, 1, SOLUTION_MT);
    const char *file = luaL_checkstring(L, 2);
    bl_error err;
    if (bl_write_vtk(*p, file, &err)) return fail(L, "%s", err.msg);
    return 0;
}

/* core.clock() -> wall-clock seconds, for timing scripts */
/* core.blocks(m): how many blocks the model has, supports included;
 * core.truncate(m, n): back to its first n (the Lua commands that make
 * several blocks undo a failure with them). */
static int core_blocks(lua_State *L)
{
    lua_pushinteger(L, check_model(L, 1)->nblocks);
    return 1;
}

static int core_truncate(lua_State *L)
{
    bl_model_truncate(check_model(L, 1), (int)luaL_checkinteger(L, 2));
    return 0;
}

static int core_clock(lua_State *L)
{
    lua_pushnumber(L, bl_clock());
    return 1;
}

/* ---- module ---------------------------------------------------------------- */

extern const struct {
    const char *name;
    const char *src;
    size_t len;
} bl_embedded_lua[];

/* package.preload loader for an embedded module; upvalue: its index. */
static int load_embedded(lua_State *L)
{
    int i = (int)lua_tointeger(L, lua_upvalueindex(1));
    char chunk[64];
    snprintf(chunk, sizeof chunk, "=[blocklim %s.lua]", bl_embedded_lua[i].name);
    if (luaL_loadbuffer(L, bl_embedded_lua[i].src, bl_embedded_lua[i].len, chunk) != LUA_OK)
        return lua_error(L);
    lua_pushvalue(L, 1);
    lua_call(L, 1, 1);
    return 1;
}

int luaopen_blocklim(lua_State *L)
{
    static const luaL_Reg model_methods[] = {
        {"block", model_block},         {"contacts", model_contacts}, {"interface", model_interface},
        {"load", model_load},           {"solve", model_solve},       {"stats", model_stats},
        {"block_info", model_block_info}, {"dim", model_dim},
        {"interface_info", model_interface_info}, {NULL, NULL}};
    static const luaL_Reg core[] = {{"model", model_new}, {"draw", core_draw},
                                     {"clock", core_clock}, {"last", core_last}, {"vtk", core_vtk},
                                     {"blocks", core_blocks}, {"truncate", core_truncate},
                                     {"check_solve", core_check_solve}, {NULL, NULL}};

    if (luaL_newmetatable(L, MODEL_MT)) {
        lua_pushcfunction(L, model_gc);
        lua_setfield(L, -2, "__gc");
        lua_pushcfunction(L, model_tostring);
        lua_setfield(L, -2, "__tostring");
        luaL_newlib(L, model_methods);
        lua_setfield(L, -2, "__index");
    }
    lua_getfield(L, -1, "__index");
    lua_remove(L, -2);
    int methods = lua_gettop(L);
    if (luaL_newmetatable(L, SOLUTION_MT)) {
        lua_pushcfunction(L, solution_gc);
        lua_setfield(L, -2, "__gc");
    }
    lua_pop(L, 1);

    /* Embedded Lua modules become "blocklim.<name>" in package.preload. */
    lua_getglobal(L, "package");
    lua_getfield(L, -1, "preload");
    for (int i = 0; bl_embedded_lua[i].name; i++) {
        lua_pushfstring(L, "blocklim.%s", bl_embedded_lua[i].name);
        lua_pushinteger(L, i);
        lua_pushcclosure(L, load_embedded, 1);
        lua_settable(L, -3);
    }
    lua_pop(L, 2);

    /* The front module gets the C core, with the model methods table. */
    lua_getglobal(L, "require");
    lua_pushstring(L, "blocklim.blocklim");
    lua_call(L, 1, 1);
    luaL_newlib(L, core);
    lua_pushvalue(L, methods);
    lua_setfield(L, -2, "model_methods");
    lua_pushnumber(L, BL_LOAD_RATIO);
    lua_setfield(L, -2, "load_ratio");
    lua_call(L, 1, 1);
    return 1;
}
