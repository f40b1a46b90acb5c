/* lua_bindings.h - the whole boundary between Lua and the C core. */
#ifndef BL_LUA_BINDINGS_H
#define BL_LUA_BINDINGS_H

#include <lua.h>

/* Opens the blocklim module and returns its table (the DSL of doc/guide.md). */
int luaopen_blocklim(lua_State *L);

#endif
