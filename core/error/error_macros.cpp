/**************************************************************************/
/*  error_macros.cpp                                                      */
/**************************************************************************/

#include "core/error/error_macros.h"

#include <cstdio>
#include <mutex>

static ErrorHandlerList *error_handler_list = nullptr;
static std::mutex error_handler_mutex;
static bool error_print_silenced = false;

void add_error_handler(ErrorHandlerList *p_handler) {
	std::lock_guard<std::mutex> lock(error_handler_mutex);
	p_handler->next = error_handler_list;
	error_handler_list = p_handler;
}

void remove_error_handler(const ErrorHandlerList *p_handler) {
	std::lock_guard<std::mutex> lock(error_handler_mutex);
	ErrorHandlerList **l = &error_handler_list;
	while (*l) {
		if (*l == p_handler) {
			*l = (*l)->next;
			return;
		}
		l = &(*l)->next;
	}
}

void set_error_print_silenced(bool p_silenced) {
	error_print_silenced = p_silenced;
}

void _err_print_error(const char *p_function, const char *p_file, int p_line, const String &p_error, const String &p_message, ErrorHandlerType p_type) {
	const String &text = p_message.empty() ? p_error : p_message;
	if (!error_print_silenced) {
		fprintf(stderr, "%s: %s\n   at: %s (%s:%d)\n", p_type == ERR_HANDLER_WARNING ? "WARNING" : "ERROR", text.c_str(), p_function, p_file, p_line);
	}
	std::lock_guard<std::mutex> lock(error_handler_mutex);
	for (ErrorHandlerList *l = error_handler_list; l; l = l->next) {
		if (l->callback) {
			l->callback(p_type, text);
		}
	}
}
