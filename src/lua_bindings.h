/* lua_bindings.h - the whole boundary between Lua and the C core. */
#ifndef BL_LUA_BINDINGS_H
#define BL_LUA_BINDINGS_H

#include <lua.h>

/* Opens the blocklim module and returns its table (the DSL of doc/guide.md). */
int luaopen_blocklim(lua_State *L);

/* The registry field where a solve stopped by Ctrl-C leaves the message of
 * the error it raised: Lua code that catches that error (compare{}, a
 * command's guard) is stopped by the prompt's hook, which raises the
 * message again rather than a bare "interrupted!" (main.c). */
#define BL_LUA_INTERRUPTED "blocklim.interrupted"

#endif
