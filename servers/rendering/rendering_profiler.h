/**************************************************************************/
/*  rendering_profiler.h                                                  */
/**************************************************************************/
/* godot-area: frame timing statistics for the `bench` command.           */
/* Records one CPU frame time and any number of named GPU pass times per  */
/* frame, discards the first N warm-up frames (thesis §5.5.1 uses 20),    */
/* and reports median, mean, min, max and p95 per pass. All times are in  */
/* milliseconds.                                                          */

#pragma once

#include "core/string/ustring.h"

#include <utility>
#include <vector>

class RenderingProfiler {
public:
	// Thesis §5.5.1: "The first 20 frames are always discarded".
	static constexpr int DEFAULT_WARMUP_FRAMES = 20;

	struct Stats {
		int count = 0; // Number of samples the statistics were computed from; 0 means "no data".
		double median = 0.0;
		double mean = 0.0;
		double min = 0.0;
		double max = 0.0;
		double p95 = 0.0;
	};

private:
	struct Frame {
		double cpu_ms = -1.0; // Negative: not recorded for this frame.
		std::vector<double> pass_ms; // Indexed like pass_names; negative: pass absent this frame.
	};

	int warmup_frames = DEFAULT_WARMUP_FRAMES;
	std::vector<String> pass_names; // In order of first appearance.
	std::vector<Frame> frames; // Every frame, warm-up included.
	bool frame_open = false;

	int _find_pass(const String &p_pass) const;
	std::vector<double> _pass_samples(int p_pass_index) const;
	std::vector<double> _cpu_samples() const;
	std::vector<double> _gpu_total_samples() const;
	double _frame_gpu_total(const Frame &p_frame) const;

public:
	// Percentile with linear interpolation between closest ranks (rank = p * (n - 1) on the
	// sorted samples; the same definition as NumPy's default). p is in [0, 1].
	static double percentile(const std::vector<double> &p_sorted_samples, double p_fraction);
	// Statistics of an arbitrary sample set (unsorted input; non-finite samples are skipped).
	static Stats compute_stats(const std::vector<double> &p_samples);

	void set_warmup_frames(int p_frames);
	int get_warmup_frames() const { return warmup_frames; }

	// Recording: begin_frame(), then set_cpu_frame_time() and add_pass_time() in any order,
	// then end_frame(). Adding the same pass twice in one frame sums the times.
	void begin_frame();
	void set_cpu_frame_time(double p_ms);
	void add_pass_time(const String &p_pass, double p_ms);
	void end_frame();
	// Convenience: one call per frame.
	void record_frame(double p_cpu_ms, const std::vector<std::pair<String, double>> &p_pass_times);

	void clear();

	int get_recorded_frame_count() const { return (int)frames.size(); } // Warm-up frames included.
	int get_measured_frame_count() const; // Warm-up frames excluded.
	const std::vector<String> &get_pass_names() const { return pass_names; }
	bool has_pass(const String &p_pass) const { return _find_pass(p_pass) >= 0; }

	// All statistics below ignore the warm-up frames.
	Stats get_cpu_stats() const;
	Stats get_pass_stats(const String &p_pass) const; // count == 0 if unknown or never measured.
	Stats get_gpu_total_stats() const; // Sum of all passes per frame.

	// CSV, one row per measured frame: "frame,cpu_ms,<pass>...,gpu_total_ms". Cells of passes
	// absent in a frame are empty. Returns false (and fills r_error) if the file cannot be written.
	bool write_csv(const String &p_path, String *r_error = nullptr) const;
	String get_csv_text() const;
	// Fixed-width text table: one row per pass plus "CPU frame" and "GPU total".
	String summary_table() const;
};
