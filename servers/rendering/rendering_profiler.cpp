/**************************************************************************/
/*  rendering_profiler.cpp                                                */
/**************************************************************************/
/* godot-area: frame timing statistics for the `bench` command.           */

#include "servers/rendering/rendering_profiler.h"

#include "core/error/error_macros.h"

#include <algorithm>
#include <cmath>
#include <fstream>

static String _csv_escape(const String &p_text) {
	if (p_text.find_first_of(",\"\n\r") == String::npos) {
		return p_text;
	}
	String out = "\"";
	for (char c : p_text) {
		if (c == '"') {
			out += "\"\"";
		} else {
			out += c;
		}
	}
	return out + "\"";
}

double RenderingProfiler::percentile(const std::vector<double> &p_sorted_samples, double p_fraction) {
	ERR_FAIL_COND_V_MSG(p_sorted_samples.empty(), 0.0, "Cannot take a percentile of an empty sample set.");
	const double fraction = std::clamp(p_fraction, 0.0, 1.0);
	const double rank = fraction * double(p_sorted_samples.size() - 1);
	const size_t lo = (size_t)std::floor(rank);
	const size_t hi = std::min(lo + 1, p_sorted_samples.size() - 1);
	const double t = rank - double(lo);
	return p_sorted_samples[lo] + (p_sorted_samples[hi] - p_sorted_samples[lo]) * t;
}

RenderingProfiler::Stats RenderingProfiler::compute_stats(const std::vector<double> &p_samples) {
	std::vector<double> sorted;
	sorted.reserve(p_samples.size());
	for (double s : p_samples) {
		if (std::isfinite(s)) {
			sorted.push_back(s);
		}
	}
	Stats stats;
	if (sorted.empty()) {
		return stats;
	}
	std::sort(sorted.begin(), sorted.end());
	double sum = 0.0;
	for (double s : sorted) {
		sum += s;
	}
	stats.count = (int)sorted.size();
	stats.mean = sum / double(sorted.size());
	stats.min = sorted.front();
	stats.max = sorted.back();
	stats.median = percentile(sorted, 0.5);
	stats.p95 = percentile(sorted, 0.95);
	return stats;
}

void RenderingProfiler::set_warmup_frames(int p_frames) {
	ERR_FAIL_COND_MSG(p_frames < 0, vformat("Warm-up frame count must be zero or positive, got %d.", p_frames));
	warmup_frames = p_frames;
}

int RenderingProfiler::_find_pass(const String &p_pass) const {
	for (size_t i = 0; i < pass_names.size(); i++) {
		if (pass_names[i] == p_pass) {
			return (int)i;
		}
	}
	return -1;
}

void RenderingProfiler::begin_frame() {
	if (frame_open) {
		WARN_PRINT("RenderingProfiler::begin_frame() called twice without end_frame(); closing the previous frame.");
		end_frame();
	}
	frames.push_back(Frame());
	frames.back().pass_ms.assign(pass_names.size(), -1.0);
	frame_open = true;
}

void RenderingProfiler::set_cpu_frame_time(double p_ms) {
	ERR_FAIL_COND_MSG(!frame_open, "set_cpu_frame_time() called outside begin_frame()/end_frame().");
	ERR_FAIL_COND_MSG(!std::isfinite(p_ms) || p_ms < 0.0, vformat("CPU frame time must be finite and non-negative, got %f ms.", p_ms));
	frames.back().cpu_ms = p_ms;
}

void RenderingProfiler::add_pass_time(const String &p_pass, double p_ms) {
	ERR_FAIL_COND_MSG(!frame_open, vformat("add_pass_time(\"%s\") called outside begin_frame()/end_frame().", p_pass.c_str()));
	ERR_FAIL_COND_MSG(p_pass.empty(), "Pass name must not be empty.");
	ERR_FAIL_COND_MSG(!std::isfinite(p_ms) || p_ms < 0.0, vformat("Time of pass \"%s\" must be finite and non-negative, got %f ms.", p_pass.c_str(), p_ms));
	int index = _find_pass(p_pass);
	if (index < 0) {
		pass_names.push_back(p_pass);
		index = (int)pass_names.size() - 1;
	}
	Frame &frame = frames.back();
	if ((int)frame.pass_ms.size() <= index) {
		frame.pass_ms.resize(index + 1, -1.0);
	}
	if (frame.pass_ms[index] < 0.0) {
		frame.pass_ms[index] = p_ms;
	} else {
		frame.pass_ms[index] += p_ms;
	}
}

void RenderingProfiler::end_frame() {
	ERR_FAIL_COND_MSG(!frame_open, "end_frame() called without begin_frame().");
	frame_open = false;
}

void RenderingProfiler::record_frame(double p_cpu_ms, const std::vector<std::pair<String, double>> &p_pass_times) {
	begin_frame();
	set_cpu_frame_time(p_cpu_ms);
	for (const std::pair<String, double> &pass : p_pass_times) {
		add_pass_time(pass.first, pass.second);
	}
	end_frame();
}

void RenderingProfiler::clear() {
	pass_names.clear();
	frames.clear();
	frame_open = false;
}

int RenderingProfiler::get_measured_frame_count() const {
	return std::max(0, (int)frames.size() - warmup_frames);
}

std::vector<double> RenderingProfiler::_pass_samples(int p_pass_index) const {
	std::vector<double> samples;
	for (size_t i = (size_t)warmup_frames; i < frames.size(); i++) {
		const Frame &frame = frames[i];
		if (p_pass_index < (int)frame.pass_ms.size() && frame.pass_ms[p_pass_index] >= 0.0) {
			samples.push_back(frame.pass_ms[p_pass_index]);
		}
	}
	return samples;
}

std::vector<double> RenderingProfiler::_cpu_samples() const {
	std::vector<double> samples;
	for (size_t i = (size_t)warmup_frames; i < frames.size(); i++) {
		if (frames[i].cpu_ms >= 0.0) {
			samples.push_back(frames[i].cpu_ms);
		}
	}
	return samples;
}

double RenderingProfiler::_frame_gpu_total(const Frame &p_frame) const {
	double total = -1.0;
	for (double ms : p_frame.pass_ms) {
		if (ms >= 0.0) {
			total = (total < 0.0 ? 0.0 : total) + ms;
		}
	}
	return total;
}

std::vector<double> RenderingProfiler::_gpu_total_samples() const {
	std::vector<double> samples;
	for (size_t i = (size_t)warmup_frames; i < frames.size(); i++) {
		const double total = _frame_gpu_total(frames[i]);
		if (total >= 0.0) {
			samples.push_back(total);
		}
	}
	return samples;
}

RenderingProfiler::Stats RenderingProfiler::get_cpu_stats() const {
	return compute_stats(_cpu_samples());
}

RenderingProfiler::Stats RenderingProfiler::get_pass_stats(const String &p_pass) const {
	const int index = _find_pass(p_pass);
	if (index < 0) {
		return Stats();
	}
	return compute_stats(_pass_samples(index));
}

RenderingProfiler::Stats RenderingProfiler::get_gpu_total_stats() const {
	return compute_stats(_gpu_total_samples());
}

String RenderingProfiler::get_csv_text() const {
	String text = "frame,cpu_ms";
	for (const String &name : pass_names) {
		text += "," + _csv_escape(name);
	}
	text += ",gpu_total_ms\n";
	for (size_t i = (size_t)warmup_frames; i < frames.size(); i++) {
		const Frame &frame = frames[i];
		text += itos((long long)i);
		text += ",";
		if (frame.cpu_ms >= 0.0) {
			text += vformat("%.6f", frame.cpu_ms);
		}
		for (size_t p = 0; p < pass_names.size(); p++) {
			text += ",";
			if (p < frame.pass_ms.size() && frame.pass_ms[p] >= 0.0) {
				text += vformat("%.6f", frame.pass_ms[p]);
			}
		}
		text += ",";
		const double total = _frame_gpu_total(frame);
		if (total >= 0.0) {
			text += vformat("%.6f", total);
		}
		text += "\n";
	}
	return text;
}

bool RenderingProfiler::write_csv(const String &p_path, String *r_error) const {
	std::ofstream file(p_path, std::ios::out | std::ios::trunc | std::ios::binary);
	if (!file.is_open()) {
		const String message = vformat("Cannot open \"%s\" for writing the profiler CSV.", p_path.c_str());
		if (r_error) {
			*r_error = message;
		}
		ERR_PRINT(message);
		return false;
	}
	const String text = get_csv_text();
	file.write(text.data(), (std::streamsize)text.size());
	file.close();
	if (file.fail()) {
		const String message = vformat("Failed while writing the profiler CSV \"%s\".", p_path.c_str());
		if (r_error) {
			*r_error = message;
		}
		ERR_PRINT(message);
		return false;
	}
	return true;
}

String RenderingProfiler::summary_table() const {
	struct Row {
		String name;
		Stats stats;
	};
	std::vector<Row> rows;
	rows.push_back({ "CPU frame", get_cpu_stats() });
	for (const String &name : pass_names) {
		rows.push_back({ name, get_pass_stats(name) });
	}
	rows.push_back({ "GPU total", get_gpu_total_stats() });

	size_t name_width = 4;
	for (const Row &row : rows) {
		name_width = std::max(name_width, row.name.size());
	}
	String table = vformat("Frames: %d recorded, %d warm-up discarded, %d measured (times in ms)\n",
			get_recorded_frame_count(), std::min(warmup_frames, get_recorded_frame_count()), get_measured_frame_count());
	table += vformat("%-*s %7s %10s %10s %10s %10s %10s\n", (int)name_width, "Pass", "Frames", "Median", "Mean", "Min", "Max", "P95");
	for (const Row &row : rows) {
		if (row.stats.count == 0) {
			table += vformat("%-*s %7d %10s %10s %10s %10s %10s\n", (int)name_width, row.name.c_str(), 0, "-", "-", "-", "-", "-");
		} else {
			table += vformat("%-*s %7d %10.3f %10.3f %10.3f %10.3f %10.3f\n", (int)name_width, row.name.c_str(), row.stats.count,
					row.stats.median, row.stats.mean, row.stats.min, row.stats.max, row.stats.p95);
		}
	}
	return table;
}
