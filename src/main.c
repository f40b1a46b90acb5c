/* main.c - blocklim's front end: command line, script runner and REPL.
 *
 * The shape follows Lua 5.4's stand-alone interpreter: a protected main
 * (pmain) opens the libraries and the blocklim module, runs the -e strings
 * and the script, then optionally reads chunks interactively.  At a terminal
 * the REPL uses GNU readline (history, completion of Lua names); on a pipe it
 * reads lines with stdio and keeps the same chunk semantics, so a model can
 * be fed to it line by line. */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <unistd.h>

#include <readline/history.h>
#include <readline/readline.h>

#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>

#include "error.h"
#include "lua_bindings.h"

#ifndef BLOCKLIM_VERSION
#define BLOCKLIM_VERSION "0.1"
#endif

#define PROGNAME "blocklim"
#define VERSION_LINE PROGNAME " " BLOCKLIM_VERSION " (" LUA_RELEASE ")"
#define PROMPT "blocklim> "
#define PROMPT_MORE "     >> "
#define REPL_CHUNKNAME "=stdin"
#define HISTORY_FILE ".blocklim_history"
#define HISTORY_MAX 1000
/* Bound on __index chains followed by completion (they may be cyclic). */
#define MAX_INDEX_DEPTH 16
/* read_chunk's result at end of input. */
#define CHUNK_EOF (-1)

extern int luaopen_blocklim(lua_State *L);

/* The state the SIGINT handler and readline's completion callback work on. */
static lua_State *globalL;
/* Set from BLOCKLIM_TRACEBACK: append a traceback to error messages. */
static int show_traceback;

struct options {
    int has_e, has_i, has_v;
    int script;   /* argv index of the script, 0 when there is none */
    int opt_end;  /* argv index where option processing stopped */
};

/* ---- messages ---------------------------------------------------------- */

static void print_usage(FILE *out)
{
    fprintf(out,
            "usage: " PROGNAME " [options] [script [args]]\n"
            "Available options are:\n"
            "  -e code    execute string 'code'\n"
            "  -i         enter interactive mode after running script/-e\n"
            "  -v         show version information\n"
            "  -h, --help show this help\n"
            "  --         stop handling options\n"
            "  -          stop handling options and run stdin as a script\n"
            "Without a script or -e, reads chunks from stdin: interactively at\n"
            "a terminal, line by line (printing expression values) on a pipe.\n"
            "Set BLOCKLIM_TRACEBACK to add tracebacks to error messages.\n");
}

/* Prints the error message on top of the stack to stderr and pops it.
 * stdout is flushed first so piped output and errors stay in order. */
static void report(lua_State *L, int with_progname)
{
    const char *msg = lua_tostring(L, -1);

    if (msg == NULL)
        msg = "(error object is not a string)";
    fflush(stdout);
    if (with_progname)
        fprintf(stderr, "%s: %s\n", PROGNAME, msg);
    else
        fprintf(stderr, "%s\n", msg);
    fflush(stderr);
    lua_pop(L, 1);
}

/* Message handler for every protected call: turns the error object into a
 * string and, when asked for, appends a traceback.  By default there is no
 * traceback: most errors a user meets are plain messages raised by the
 * module's C functions, where the traceback is noise. */
static int msghandler(lua_State *L)
{
    const char *msg = lua_tostring(L, 1);

    if (msg == NULL) {
        if (luaL_callmeta(L, 1, "__tostring") && lua_type(L, -1) == LUA_TSTRING)
            msg = lua_tostring(L, -1);
        else
            msg = lua_pushfstring(L, "(error object is a %s value)",
                                  luaL_typename(L, 1));
    }
    if (show_traceback)
        luaL_traceback(L, L, msg, 1);
    else
        lua_pushstring(L, msg);
    return 1;
}

/* ---- interruption ------------------------------------------------------ */

/* Hook armed by the SIGINT handler: stops running Lua code with an error at
 * the next return, line or instruction (past a call, below). */
static void stop_hook(lua_State *L, lua_Debug *ar)
{
    /* Not at a call: a C function that saw the flag (a solve) has already
     * raised its own error, and the call may be of a message handler (the
     * prompt's, or xpcall's), which must run; at the next instruction
     * instead. */
    if (ar->event == LUA_HOOKCALL) {
        lua_sethook(L, stop_hook, LUA_MASKLINE | LUA_MASKCOUNT, 1);
        return;
    }
    lua_sethook(L, NULL, 0, 0);
    /* Where Lua code caught that error (compare{}, a command's guard, a
     * pcall or xpcall of the user's), it stops with the same message. */
    lua_getfield(L, LUA_REGISTRYINDEX, BL_LUA_INTERRUPTED);
    if (lua_type(L, -1) == LUA_TSTRING) {
        lua_pushnil(L);
        lua_setfield(L, LUA_REGISTRYINDEX, BL_LUA_INTERRUPTED);
        lua_error(L);
    }
    lua_pop(L, 1);
    luaL_error(L, "interrupted!");
}

/* Both actions are fit for a signal handler: the first only sets the
 * sig_atomic_t that the module's C loops poll; the second is lua_sethook,
 * which Lua's sources allow to be called from a signal (lua.c does the
 * same).  Lua code then stops at its next hook point. */
static void on_sigint(int sig)
{
    (void)sig;
    bl_interrupt_request();
    lua_sethook(globalL, stop_hook,
                LUA_MASKCALL | LUA_MASKRET | LUA_MASKLINE | LUA_MASKCOUNT, 1);
}

static void set_sigint(void (*handler)(int))
{
    struct sigaction sa;

    memset(&sa, 0, sizeof sa);
    sa.sa_handler = handler;
    sigemptyset(&sa.sa_mask);
    /* SA_RESETHAND: the handler runs once, so a second Ctrl-C kills the
     * process -- the way out of C code that never polls the flag.  No
     * SA_RESTART, so a blocked read in Lua code returns at once. */
    sa.sa_flags = handler == SIG_DFL ? 0 : SA_RESETHAND;
    sigaction(SIGINT, &sa, NULL);
}

/* Calls the function below narg arguments with the message handler, with
 * Ctrl-C enabled only for the duration of the call. */
static int docall(lua_State *L, int narg, int nres)
{
    int base = lua_gettop(L) - narg;
    int status;

    lua_pushcfunction(L, msghandler);
    lua_insert(L, base);
    globalL = L;
    bl_interrupt_clear();
    lua_pushnil(L);
    lua_setfield(L, LUA_REGISTRYINDEX, BL_LUA_INTERRUPTED);
    set_sigint(on_sigint);
    status = lua_pcall(L, narg, nres, base);
    set_sigint(SIG_DFL);
    /* A Ctrl-C after the last hook point leaves the stop hook armed; disarm
     * it so the next chunk does not fail at once.  Other hooks (set with
     * debug.sethook) are left alone. */
    if (lua_gethook(L) == stop_hook)
        lua_sethook(L, NULL, 0, 0);
    lua_remove(L, base);
    fflush(stdout);
    return status;
}

/* ---- history ----------------------------------------------------------- */

static char history_path[4096];
static int history_added;   /* entries added during this session */

/* atexit handler, so os.exit also saves the history.  The session's
 * entries are appended, which keeps those of sessions running side by side.
 * The file is then trimmed by entries: history_truncate_file counts lines
 * and would split multi-line entries from their stamps, so the file is read
 * back into the (stifled) list, which keeps the newest HISTORY_MAX entries,
 * and rewritten. */
static void history_save(void)
{
    int n = history_added < history_length ? history_added : history_length;

    if (n == 0)
        return;
    if (append_history(n, history_path) != 0)   /* e.g. no file yet */
        write_history(history_path);
    clear_history();
    if (read_history(history_path) == 0)
        write_history(history_path);
}

static void history_open(void)
{
    const char *home = getenv("HOME");
    int len;

    using_history();
    stifle_history(HISTORY_MAX);
    /* Timestamp lines ("#<seconds>") delimit entries in the file, which
     * lets a multi-line chunk come back as one entry in the next session.
     * readline stamps entries only when the comment character is set. */
    history_comment_char = '#';
    history_write_timestamps = 1;
    if (home == NULL || home[0] == '\0')
        return;
    len = snprintf(history_path, sizeof history_path, "%s/%s", home,
                   HISTORY_FILE);
    if (len < 0 || (size_t)len >= sizeof history_path)
        return;
    read_history(history_path);
    atexit(history_save);
}

/* Adds a chunk to the history unless it is blank or repeats the last one. */
static void history_add(const char *text)
{
    HIST_ENTRY *last;

    if (text[strspn(text, " \t\r\n")] == '\0')
        return;
    last = history_get(history_base + history_length - 1);
    if (last != NULL && strcmp(last->line, text) == 0)
        return;
    add_history(text);
    history_added++;
}

/* ---- completion -------------------------------------------------------- */

struct candidates {
    char **items;      /* malloc'd full words, e.g. "string.format" */
    size_t n, cap;
    size_t handed;     /* items already given to readline */
};

/* What completion works on, passed to the protected collector. */
struct completion {
    const char *text;
    struct candidates *out;
};

static const char *const lua_keywords[] = {
    "and", "break", "do", "else", "elseif", "end", "false", "for",
    "function", "goto", "if", "in", "local", "nil", "not", "or", "repeat",
    "return", "then", "true", "until", "while", NULL
};

static struct candidates *pending;   /* read by the readline generator */

static void add_candidate(struct candidates *c, const char *prefix,
                          size_t prefix_len, const char *word)
{
    size_t len = strlen(word);
    char *item;

    if (c->n == c->cap) {
        size_t cap = c->cap ? 2 * c->cap : 32;
        char **items = realloc(c->items, cap * sizeof *items);
        if (items == NULL)
            return;
        c->items = items;
        c->cap = cap;
    }
    item = malloc(prefix_len + len + 1);
    if (item == NULL)
        return;
    memcpy(item, prefix, prefix_len);
    memcpy(item + prefix_len, word, len + 1);
    c->items[c->n++] = item;
}

static int is_identifier_start(char c)
{
    return c == '_' || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

static int is_identifier(const char *s)
{
    const char *p;

    if (!is_identifier_start(s[0]))
        return 0;
    for (p = s + 1; *p; p++)
        if (!(*p == '_' || (*p >= 'a' && *p <= 'z') ||
              (*p >= 'A' && *p <= 'Z') || (*p >= '0' && *p <= '9')))
            return 0;
    return 1;
}

/* Replaces the value on top with its metatable's __index when that is a
 * table and returns 1; otherwise pops the value and returns 0. */
static int step_index_chain(lua_State *L)
{
    if (lua_getmetatable(L, -1)) {
        lua_pushliteral(L, "__index");
        if (lua_rawget(L, -2) == LUA_TTABLE) {
            lua_replace(L, -3);
            lua_pop(L, 1);
            return 1;
        }
        lua_pop(L, 2);
    }
    lua_pop(L, 1);
    return 0;
}

/* Replaces the value on top with its field name (or, name NULL, its
 * entry index), found without running any code (completion must not call
 * __index functions): a raw get if it is a table, then along its chain of
 * __index tables.  nil when not found. */
static void peek_field(lua_State *L, const char *name, size_t len, lua_Integer index)
{
    int depth;

    for (depth = 0; depth < MAX_INDEX_DEPTH; depth++) {
        if (lua_type(L, -1) == LUA_TTABLE) {
            if (name != NULL)
                lua_pushlstring(L, name, len);
            else
                lua_pushinteger(L, index);
            if (lua_rawget(L, -2) != LUA_TNIL) {
                lua_remove(L, -2);
                return;
            }
            lua_pop(L, 1);
        }
        if (!step_index_chain(L))
            break;
    }
    if (depth == MAX_INDEX_DEPTH)
        lua_pop(L, 1);
    lua_pushnil(L);
}

/* Steps the value on top through one "[k]" at *p, k an integer literal,
 * advancing *p past it; 0 when *p holds anything else (a variable, an
 * expression, a string: quotes break readline's words). */
static int peek_bracket(lua_State *L, const char **p)
{
    const char *q = *p + 1, *end;
    lua_Integer k = 0;

    for (end = q; *end >= '0' && *end <= '9' && end - q < 15; end++)
        k = 10 * k + (*end - '0');
    if (end == q || *end != ']')
        return 0;
    peek_field(L, NULL, 0, k);
    *p = end + 1;
    return 1;
}

/* Adds the string keys of the table on top that extend partial.  Names
 * starting with "__" (metamethods) are shown only when asked for. */
static void add_table_keys(lua_State *L, struct candidates *c,
                           const char *prefix, size_t prefix_len,
                           const char *partial, int functions_only)
{
    size_t plen = strlen(partial);
    /* names that begin with "_" (metamethods, a result's _solution, _G)
     * only when the word does */
    int want_hidden = partial[0] == '_';

    lua_pushnil(L);
    while (lua_next(L, -2)) {
        if (lua_type(L, -2) == LUA_TSTRING) {
            const char *key = lua_tostring(L, -2);
            if (strncmp(key, partial, plen) == 0 && is_identifier(key) &&
                (want_hidden || key[0] != '_') &&
                (!functions_only || lua_type(L, -1) == LUA_TFUNCTION))
                add_candidate(c, prefix, prefix_len, key);
        }
        lua_pop(L, 1);
    }
}

/* Adds the names in the __fields list of the metatable of the table on
 * top that extend partial: fields an __index function gives (a
 * mechanism entry's vx, vy, omega), which completion cannot call. */
static void add_listed_fields(lua_State *L, struct candidates *c, const char *prefix,
                              size_t prefix_len, const char *partial)
{
    size_t plen = strlen(partial);

    if (!lua_getmetatable(L, -1))
        return;
    lua_pushliteral(L, "__fields");
    if (lua_rawget(L, -2) == LUA_TTABLE) {
        for (lua_Integer i = 1; lua_rawgeti(L, -1, i) == LUA_TSTRING; i++) {
            const char *name = lua_tostring(L, -1);
            if (strncmp(name, partial, plen) == 0 && is_identifier(name))
                add_candidate(c, prefix, prefix_len, name);
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    lua_pop(L, 2);
}

/* Protected part of completion.  The word begins after the last '[' left
 * open (t[na completes a global); it is split at its last '.' or ':'
 * outside brackets; the part before is walked from the globals through
 * names and literal indices (r.interfaces[3].st), the part after is
 * matched against the fields of the value reached and of its __index
 * tables. */
static int collect_completions(lua_State *L)
{
    const struct completion *comp = lua_touserdata(L, 1);
    const char *text = comp->text;
    const char *word = text, *sep = NULL, *p, *partial;
    const char *opened[16];   /* the '['s not closed yet */
    int depth, i, open = 0;

    for (p = text; *p; p++) {
        if (*p == '[' && open < 16)
            opened[open++] = p;
        else if (*p == ']' && open > 0)
            open--;
    }
    if (open > 0)
        word = opened[open - 1] + 1;
    for (p = word, depth = 0; *p; p++) {
        depth += *p == '[' ? 1 : *p == ']' ? -1 : 0;
        if (depth == 0 && (*p == '.' || *p == ':'))
            sep = p;
    }
    lua_pushglobaltable(L);
    if (sep == NULL) {
        partial = word;
        for (i = 0; lua_keywords[i] != NULL; i++)
            if (strncmp(lua_keywords[i], word, strlen(word)) == 0)
                add_candidate(comp->out, text, (size_t)(word - text), lua_keywords[i]);
    } else {
        if (!is_identifier_start(*word))   /* after a call, "current():", the value is unknown */
            return 0;
        for (p = word; p < sep;) {
            if (*p == '[') {
                if (!peek_bracket(L, &p))
                    return 0;
            } else {
                if (p != word && *p++ == ':')   /* "a:b.c" is not an access */
                    return 0;
                const char *end = p;
                while (end < sep && *end != '.' && *end != ':' && *end != '[')
                    end++;
                peek_field(L, p, (size_t)(end - p), 0);
                p = end;
            }
            if (lua_isnil(L, -1))
                return 0;
        }
        partial = sep + 1;
    }
    for (depth = 0; depth < MAX_INDEX_DEPTH; depth++) {
        if (lua_type(L, -1) == LUA_TTABLE) {
            add_table_keys(L, comp->out, text, (size_t)(partial - text),
                           partial, sep != NULL && *sep == ':');
            add_listed_fields(L, comp->out, text, (size_t)(partial - text), partial);
        }
        if (!step_index_chain(L))
            break;
    }
    return 0;
}

/* readline generator: hands out the collected candidates (readline frees
 * them). */
static char *next_candidate(const char *text, int state)
{
    (void)text;
    (void)state;
    if (pending == NULL || pending->handed == pending->n)
        return NULL;
    return pending->items[pending->handed++];
}

static char **complete(const char *text, int start, int end)
{
    struct candidates c = {NULL, 0, 0, 0};
    struct completion comp;
    char **matches = NULL;
    int top = lua_gettop(globalL);

    (void)start;
    (void)end;
    rl_attempted_completion_over = 1;     /* no file-name fallback */
    rl_completion_append_character = '\0';
    comp.text = text;
    comp.out = &c;
    /* Nothing pushed here allocates, so no Lua error can escape into
     * readline; everything else runs under lua_pcall. */
    if (lua_checkstack(globalL, 2)) {
        lua_pushcfunction(globalL, collect_completions);
        lua_pushlightuserdata(globalL, &comp);
        if (lua_pcall(globalL, 1, 0, 0) == LUA_OK && c.n > 0) {
            pending = &c;
            matches = rl_completion_matches(text, next_candidate);
            pending = NULL;
        }
    }
    lua_settop(globalL, top);
    while (c.handed < c.n)
        free(c.items[c.handed++]);
    free(c.items);
    return matches;
}

/* ---- the REPL ---------------------------------------------------------- */

/* Set by Ctrl-C at the prompt: the chunk being typed is dropped. */
static volatile sig_atomic_t input_cancelled;

/* Ctrl-C while a line is being typed abandons it, and with it the lines
 * of an unfinished chunk before it, and shows a fresh prompt, as shells
 * do; it does not end the session.  Readline hands the signal on to this
 * handler after its own clean-up (it echoes ^C), from read_key. */
static void on_idle_sigint(int sig)
{
    (void)sig;
    input_cancelled = 1;
    rl_replace_line("", 0);
}

/* Readline's key reader: as rl_getc, but a read interrupted by Ctrl-C
 * ends the line at once (an empty line, which read_chunk drops), where
 * rl_getc would wait for the next key. */
static int read_key(FILE *stream)
{
    for (;;) {
        unsigned char c;
        ssize_t r = read(fileno(stream), &c, 1);
        if (r == 1)
            return c;
        if (r < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            /* a terminal left non-blocking by another program: block again */
            int fl = fcntl(fileno(stream), F_GETFL, 0);
            if (fl >= 0 && (fl & O_NONBLOCK) &&
                fcntl(fileno(stream), F_SETFL, fl & ~O_NONBLOCK) == 0)
                continue;
        }
        if (r == 0 || errno != EINTR)
            return EOF;
        rl_check_signals();   /* readline's handling, then ours */
        if (input_cancelled)
            return '\n';
    }
}

/* Returns the next input line without its newline (malloc'd), or NULL at
 * end of input. */
static char *read_line(int interactive, int first)
{
    char *line = NULL;
    size_t cap = 0;
    ssize_t len;

    if (interactive) {
        struct sigaction sa, old;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_idle_sigint;
        sigemptyset(&sa.sa_mask);
        sigaction(SIGINT, &sa, &old);
        line = readline(first ? PROMPT : PROMPT_MORE);
        sigaction(SIGINT, &old, NULL);
        return line;
    }
    len = getline(&line, &cap, stdin);
    if (len < 0) {
        free(line);
        return NULL;
    }
    while (len > 0 && (line[len - 1] == '\n' || line[len - 1] == '\r'))
        line[--len] = '\0';
    return line;
}

/* A syntax error at "<eof>" means the chunk only needs more lines. */
static int is_incomplete(lua_State *L, int status)
{
    static const char mark[] = "<eof>";
    size_t len;
    const char *msg;

    if (status != LUA_ERRSYNTAX)
        return 0;
    msg = lua_tolstring(L, -1, &len);
    return len >= sizeof mark - 1 &&
           strcmp(msg + len - (sizeof mark - 1), mark) == 0;
}

/* Compiles "return <text>" for the text on top; on success pushes the
 * function and returns 1, otherwise leaves the stack as it was. */
static int compile_as_return(lua_State *L)
{
    const char *code = lua_pushfstring(L, "return %s", lua_tostring(L, -1));
    int status = luaL_loadbuffer(L, code, strlen(code), REPL_CHUNKNAME);

    lua_remove(L, -2);
    if (status == LUA_OK)
        return 1;
    lua_pop(L, 1);
    return 0;
}

/* Reads and compiles one chunk, leaving the function (status LUA_OK) or an
 * error message on the stack.  A line is first tried as an expression, so
 * its values get printed; otherwise lines accumulate while the only
 * complaint is a premature end of input, each time tried as an expression
 * first too (a wall{...} typed over several lines prints its blocks).
 * Returns CHUNK_EOF, with nothing pushed, at end of input. */
static int read_chunk(lua_State *L, int interactive)
{
    char *line;
    int status;

again:
    input_cancelled = 0;
    line = read_line(interactive, 1);
    if (line == NULL)
        return CHUNK_EOF;
    if (input_cancelled) {
        free(line);
        goto again;
    }
    if (line[0] == '=')   /* "=expr", as in Lua 5.1-5.3 */
        lua_pushfstring(L, "return %s", line + 1);
    else
        lua_pushstring(L, line);
    free(line);

    if (compile_as_return(L)) {
        status = LUA_OK;
    } else {
        for (;;) {
            size_t len;
            const char *code = lua_tolstring(L, -1, &len);
            status = luaL_loadbuffer(L, code, len, REPL_CHUNKNAME);
            if (!is_incomplete(L, status) ||
                (line = read_line(interactive, 0)) == NULL)
                break;   /* done, or input ended inside the chunk */
            lua_pop(L, 1);
            if (input_cancelled) {   /* the unfinished chunk is dropped */
                free(line);
                lua_pop(L, 1);
                goto again;
            }
            lua_pushliteral(L, "\n");
            lua_pushstring(L, line);
            free(line);
            lua_concat(L, 3);
            if (compile_as_return(L)) {   /* an expression over several lines */
                status = LUA_OK;
                break;
            }
        }
    }
    if (interactive)
        history_add(lua_tostring(L, -2));
    lua_remove(L, -2);   /* the text */
    return status;
}

/* Prints the values above base: with blocklim.report's print_values
 * (a plain table as its fields), else the global print. */
static int print_results(lua_State *L, int base)
{
    int n = lua_gettop(L) - base;

    if (n == 0)
        return LUA_OK;
    luaL_checkstack(L, LUA_MINSTACK, "too many results to print");
    lua_getfield(L, LUA_REGISTRYINDEX, LUA_LOADED_TABLE);
    int shown = lua_getfield(L, -1, "blocklim.report") == LUA_TTABLE &&
                lua_getfield(L, -1, "print_values") == LUA_TFUNCTION;
    if (shown) {
        lua_replace(L, -3);
        lua_pop(L, 1);
    } else {
        lua_settop(L, base + n);
        lua_getglobal(L, "print");
    }
    lua_insert(L, base + 1);
    return docall(L, n, 0);
}

static void print_banner(lua_State *L)
{
    int has_help = lua_getglobal(L, "help") != LUA_TNIL;

    lua_pop(L, 1);
    printf("%s%s\n", VERSION_LINE,
           has_help ? " -- type help for the commands" : "");
    fflush(stdout);
}

static void setup_readline(void)
{
    rl_readline_name = "blocklim";
    /* '.', ':', '[' and ']' are not breaks, so "string.fo" and "r.interfaces[3].st"
     * are one word to complete. */
    rl_basic_word_break_characters = " \t\n\"'`\\<>=;+-*/%^~#&|,(){}";
    rl_attempted_completion_function = complete;
    rl_getc_function = read_key;
    history_open();
}

/* Runs chunks until end of input.  Interactively errors are just shown;
 * on a pipe the result is 0 if any chunk failed, so the exit status tells. */
static int repl(lua_State *L, int quiet)
{
    int interactive = isatty(STDIN_FILENO);
    int failed = 0;

    if (interactive) {
        setup_readline();
        if (!quiet)
            print_banner(L);
    }
    for (;;) {
        int base = lua_gettop(L);
        int status = read_chunk(L, interactive);
        if (status == CHUNK_EOF)
            break;
        if (status == LUA_OK)
            status = docall(L, 0, LUA_MULTRET);
        if (status == LUA_OK)
            status = print_results(L, base);
        if (status != LUA_OK) {
            report(L, 0);
            failed = 1;
        }
        lua_settop(L, base);
    }
    if (interactive) {   /* leave the shell prompt on a fresh line */
        putchar('\n');
        fflush(stdout);
    }
    return interactive || !failed;
}

/* ---- command line ------------------------------------------------------ */

/* Returns 0 to go on, 1 after printing help, -1 on a bad command line. */
static int parse_args(int argc, char **argv, struct options *opt)
{
    int i;

    memset(opt, 0, sizeof *opt);
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (a[0] != '-' || a[1] == '\0') {   /* script name or "-" */
            opt->script = i;
            break;
        }
        if (strcmp(a, "--") == 0) {
            if (i + 1 < argc)
                opt->script = i + 1;
            break;
        }
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            print_usage(stdout);
            return 1;
        } else if (strcmp(a, "-i") == 0) {
            opt->has_i = 1;
        } else if (strcmp(a, "-v") == 0) {
            opt->has_v = 1;
        } else if (a[1] == 'e') {   /* "-e code" or "-ecode" */
            opt->has_e = 1;
            if (a[2] == '\0' && ++i == argc) {
                fprintf(stderr, PROGNAME ": '-e' needs an argument\n");
                print_usage(stderr);
                return -1;
            }
        } else {
            fprintf(stderr, PROGNAME ": unrecognized option '%s'\n", a);
            print_usage(stderr);
            return -1;
        }
    }
    opt->opt_end = i;
    return 0;
}

/* The global arg, as in lua: arg[0] is the script, arg[1..] its arguments,
 * negative indices the interpreter and its options.  Without a script,
 * arg[0] is the interpreter. */
static void create_arg_table(lua_State *L, int argc, char **argv, int script)
{
    int i;

    lua_createtable(L, argc - script - 1, script + 1);
    for (i = 0; i < argc; i++) {
        lua_pushstring(L, argv[i]);
        lua_rawseti(L, -2, i - script);
    }
    lua_setglobal(L, "arg");
}

/* Runs the -e strings in order; returns 0 at the first failure. */
static int run_strings(lua_State *L, char **argv, const struct options *opt)
{
    int i;

    for (i = 1; i < opt->opt_end; i++) {
        const char *code;
        int status;
        if (argv[i][1] != 'e')
            continue;
        code = argv[i][2] != '\0' ? argv[i] + 2 : argv[++i];
        status = luaL_loadbuffer(L, code, strlen(code), "=(command line)");
        if (status == LUA_OK)
            status = docall(L, 0, 0);
        if (status != LUA_OK) {
            report(L, 1);
            return 0;
        }
    }
    return 1;
}

/* Runs the script with its arguments as "..."; "-" means stdin, except
 * after "--" where it is a file of that name. */
static int run_script(lua_State *L, int argc, char **argv, int script)
{
    const char *fname = argv[script];
    int status, i;

    if (strcmp(fname, "-") == 0 && strcmp(argv[script - 1], "--") != 0)
        fname = NULL;
    status = luaL_loadfile(L, fname);
    if (status == LUA_OK) {
        luaL_checkstack(L, argc - script, "too many arguments to script");
        for (i = script + 1; i < argc; i++)
            lua_pushstring(L, argv[i]);
        status = docall(L, argc - script - 1, 0);
    }
    if (status != LUA_OK) {
        report(L, 1);
        return 0;
    }
    return 1;
}

/* Opens the module, makes it the global "blocklim" and lets it copy the
 * DSL names into _G. */
static void open_module(lua_State *L)
{
    luaL_requiref(L, "blocklim", luaopen_blocklim, 1);
    if (lua_getfield(L, -1, "globals") != LUA_TFUNCTION)
        luaL_error(L, "module 'blocklim' has no function 'globals'");
    lua_call(L, 0, 0);
    lua_pop(L, 1);
}

/* Everything that touches Lua runs here, inside lua_pcall, so even errors
 * outside any chunk (e.g. out of memory) are reported.  Returns a boolean:
 * whether the run succeeded. */
static int pmain(lua_State *L)
{
    int argc = (int)lua_tointeger(L, 1);
    char **argv = lua_touserdata(L, 2);
    const struct options *opt = lua_touserdata(L, 3);
    int ok;

    globalL = L;
    luaL_checkversion(L);
    if (opt->has_v) {
        printf("%s\n", VERSION_LINE);
        fflush(stdout);
    }
    luaL_openlibs(L);
    open_module(L);
    create_arg_table(L, argc, argv, opt->script);
    ok = run_strings(L, argv, opt) &&
         (opt->script == 0 || run_script(L, argc, argv, opt->script));
    /* Like lua: the prompt comes with -i, or when there is nothing else to
     * do (no script, no -e, no -v). */
    if (ok && (opt->has_i || (opt->script == 0 && !opt->has_e && !opt->has_v)))
        ok = repl(L, opt->has_v);
    lua_pushboolean(L, ok);
    return 1;
}

/* Settings the libraries read when they load, before main: the program
 * sets them and starts itself again, once; a user's own settings win.
 *
 * The interior point's OpenMP threads wait for work by spinning 300,000
 * times (libgomp's default) before they sleep: alone that is what makes
 * its short parallel loops fast, but beside another busy process the
 * spinning threads take the cores from it (two 10,050-block solves at
 * once: 20 s each against 5 s).  A spin of 3,000 costs nothing alone.
 *
 * OpenBLAS picks its kernels from the processor, and kernels of other
 * widths round differently inside CHOLMOD's factorizations.  A sequence
 * of LPs follows that round-off: the 1,040-block wall took 13 LPs with the
 * AVX2 kernels and 18 with the AVX-512 ones, and the dome of the tests
 * certified with the first and not within 100 LPs with the second.  So on
 * every x86-64 processor with AVX2 and FMA the program takes OpenBLAS's
 * Haswell kernels, as fast here per iteration as the AVX-512 ones, and a
 * model gives the same answer, LP for LP, on every such machine
 * (doc/performance.md, "Kernels and round-off").
 *
 * OpenBLAS starts a thread per further core when it loads, which spins for
 * about 0.1 s of CPU before it sleeps; nothing here ever hands BLAS work to
 * it (bl_one_thread, error.h), so it is not started. */
static void fixed_environment(char **argv)
{
    int changed = 0;
    if (!getenv("OMP_WAIT_POLICY") && !getenv("GOMP_SPINCOUNT"))
        changed |= setenv("GOMP_SPINCOUNT", "3000", 1) == 0;
    if (!getenv("OPENBLAS_NUM_THREADS"))
        changed |= setenv("OPENBLAS_NUM_THREADS", "1", 1) == 0;
#if defined(__x86_64__) && defined(__GNUC__)
    if (!getenv("OPENBLAS_CORETYPE") && __builtin_cpu_supports("avx2") &&
        __builtin_cpu_supports("fma"))
        changed |= setenv("OPENBLAS_CORETYPE", "Haswell", 1) == 0;
#endif
    if (changed) execv("/proc/self/exe", argv);
    /* not re-executed (no /proc): go on with the libraries' defaults */
}

int main(int argc, char **argv)
{
    struct options opt;
    lua_State *L;
    int status, ok, parsed;

    fixed_environment(argv);
    parsed = parse_args(argc, argv, &opt);
    if (parsed != 0)
        return parsed > 0 ? EXIT_SUCCESS : EXIT_FAILURE;
    show_traceback = getenv("BLOCKLIM_TRACEBACK") != NULL;
    L = luaL_newstate();
    if (L == NULL) {
        fprintf(stderr, PROGNAME ": cannot create Lua state: not enough memory\n");
        return EXIT_FAILURE;
    }
    lua_pushcfunction(L, pmain);
    lua_pushinteger(L, argc);
    lua_pushlightuserdata(L, argv);
    lua_pushlightuserdata(L, &opt);
    status = lua_pcall(L, 3, 1, 0);
    ok = status == LUA_OK && lua_toboolean(L, -1);
    if (status != LUA_OK)
        report(L, 1);
    lua_close(L);
    return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
