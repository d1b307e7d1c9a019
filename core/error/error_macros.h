/**************************************************************************/
/*  error_macros.h                                                        */
/**************************************************************************/
/* Error macros in Godot's spirit: check at public boundaries, print a    */
/* message that names the problem, return a safe value. Never crash.      */

#pragma once

#include "core/string/ustring.h"

#include <functional>

enum ErrorHandlerType {
	ERR_HANDLER_ERROR,
	ERR_HANDLER_WARNING,
};

// Prints "ERROR: <message>\n   at: <function> (<file>:<line>)" to stderr and
// notifies the installed handlers (tests use them to assert on messages).
void _err_print_error(const char *p_function, const char *p_file, int p_line, const String &p_error, const String &p_message = String(), ErrorHandlerType p_type = ERR_HANDLER_ERROR);

struct ErrorHandlerList {
	std::function<void(ErrorHandlerType p_type, const String &p_text)> callback;
	ErrorHandlerList *next = nullptr;
};
void add_error_handler(ErrorHandlerList *p_handler);
void remove_error_handler(const ErrorHandlerList *p_handler);

// When true, error/warning text is not printed (handlers still run). Tests of bad input use it.
void set_error_print_silenced(bool p_silenced);

#define _STR(m_x) #m_x
#define _MKSTR(m_x) _STR(m_x)

#define ERR_PRINT(m_msg) _err_print_error(__FUNCTION__, __FILE__, __LINE__, String(m_msg))
#define WARN_PRINT(m_msg) _err_print_error(__FUNCTION__, __FILE__, __LINE__, String(m_msg), String(), ERR_HANDLER_WARNING)
#define WARN_PRINT_ONCE(m_msg)                                                                                \
	do {                                                                                                      \
		static bool _warned = false;                                                                          \
		if (!_warned) {                                                                                       \
			_err_print_error(__FUNCTION__, __FILE__, __LINE__, String(m_msg), String(), ERR_HANDLER_WARNING); \
			_warned = true;                                                                                   \
		}                                                                                                     \
	} while (0)

#define ERR_FAIL_COND_MSG(m_cond, m_msg)                                                                              \
	if (__builtin_expect(!!(m_cond), 0)) {                                                                            \
		_err_print_error(__FUNCTION__, __FILE__, __LINE__, "Condition \"" _STR(m_cond) "\" is true.", String(m_msg)); \
		return;                                                                                                       \
	} else                                                                                                            \
		((void)0)
#define ERR_FAIL_COND(m_cond) ERR_FAIL_COND_MSG(m_cond, "")

#define ERR_FAIL_COND_V_MSG(m_cond, m_retval, m_msg)                                                                                             \
	if (__builtin_expect(!!(m_cond), 0)) {                                                                                                       \
		_err_print_error(__FUNCTION__, __FILE__, __LINE__, "Condition \"" _STR(m_cond) "\" is true. Returning: " _STR(m_retval), String(m_msg)); \
		return m_retval;                                                                                                                         \
	} else                                                                                                                                       \
		((void)0)
#define ERR_FAIL_COND_V(m_cond, m_retval) ERR_FAIL_COND_V_MSG(m_cond, m_retval, "")

#define ERR_FAIL_NULL_MSG(m_param, m_msg)                                                                              \
	if (__builtin_expect(!(m_param), 0)) {                                                                             \
		_err_print_error(__FUNCTION__, __FILE__, __LINE__, "Parameter \"" _STR(m_param) "\" is null.", String(m_msg)); \
		return;                                                                                                        \
	} else                                                                                                             \
		((void)0)
#define ERR_FAIL_NULL(m_param) ERR_FAIL_NULL_MSG(m_param, "")

#define ERR_FAIL_NULL_V_MSG(m_param, m_retval, m_msg)                                                                  \
	if (__builtin_expect(!(m_param), 0)) {                                                                             \
		_err_print_error(__FUNCTION__, __FILE__, __LINE__, "Parameter \"" _STR(m_param) "\" is null.", String(m_msg)); \
		return m_retval;                                                                                               \
	} else                                                                                                             \
		((void)0)
#define ERR_FAIL_NULL_V(m_param, m_retval) ERR_FAIL_NULL_V_MSG(m_param, m_retval, "")

#define ERR_FAIL_INDEX_MSG(m_index, m_size, m_msg)                                                                                                                                                           \
	if (__builtin_expect((m_index) < 0 || (m_index) >= (m_size), 0)) {                                                                                                                                       \
		_err_print_error(__FUNCTION__, __FILE__, __LINE__, vformat("Index " _STR(m_index) " = %lld is out of bounds (" _STR(m_size) " = %lld).", (long long)(m_index), (long long)(m_size)), String(m_msg)); \
		return;                                                                                                                                                                                              \
	} else                                                                                                                                                                                                   \
		((void)0)
#define ERR_FAIL_INDEX(m_index, m_size) ERR_FAIL_INDEX_MSG(m_index, m_size, "")

#define ERR_FAIL_INDEX_V_MSG(m_index, m_size, m_retval, m_msg)                                                                                                                                               \
	if (__builtin_expect((m_index) < 0 || (m_index) >= (m_size), 0)) {                                                                                                                                       \
		_err_print_error(__FUNCTION__, __FILE__, __LINE__, vformat("Index " _STR(m_index) " = %lld is out of bounds (" _STR(m_size) " = %lld).", (long long)(m_index), (long long)(m_size)), String(m_msg)); \
		return m_retval;                                                                                                                                                                                     \
	} else                                                                                                                                                                                                   \
		((void)0)
#define ERR_FAIL_INDEX_V(m_index, m_size, m_retval) ERR_FAIL_INDEX_V_MSG(m_index, m_size, m_retval, "")

#define ERR_FAIL_MSG(m_msg)                                                                  \
	do {                                                                                     \
		_err_print_error(__FUNCTION__, __FILE__, __LINE__, "Method failed.", String(m_msg)); \
		return;                                                                              \
	} while (0)
#define ERR_FAIL_V_MSG(m_retval, m_msg)                                                                                 \
	do {                                                                                                                \
		_err_print_error(__FUNCTION__, __FILE__, __LINE__, "Method failed. Returning: " _STR(m_retval), String(m_msg)); \
		return m_retval;                                                                                                \
	} while (0)
#define ERR_FAIL_V(m_retval) ERR_FAIL_V_MSG(m_retval, "")

#define ERR_CONTINUE_MSG(m_cond, m_msg)                                                                                           \
	if (__builtin_expect(!!(m_cond), 0)) {                                                                                        \
		_err_print_error(__FUNCTION__, __FILE__, __LINE__, "Condition \"" _STR(m_cond) "\" is true. Continuing.", String(m_msg)); \
		continue;                                                                                                                 \
	} else                                                                                                                        \
		((void)0)
#define ERR_CONTINUE(m_cond) ERR_CONTINUE_MSG(m_cond, "")

#define ERR_BREAK_MSG(m_cond, m_msg)                                                                                            \
	if (__builtin_expect(!!(m_cond), 0)) {                                                                                      \
		_err_print_error(__FUNCTION__, __FILE__, __LINE__, "Condition \"" _STR(m_cond) "\" is true. Breaking.", String(m_msg)); \
		break;                                                                                                                  \
	} else                                                                                                                      \
		((void)0)
#define ERR_BREAK(m_cond) ERR_BREAK_MSG(m_cond, "")
