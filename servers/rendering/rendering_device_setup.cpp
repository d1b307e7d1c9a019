/**************************************************************************/
/*  rendering_device_setup.cpp                                            */
/**************************************************************************/
/* RenderingDevice: Vulkan instance and device creation (device choice,   */
/* validation layer, debug messenger, optional presentation extensions),  */
/* teardown, device info and validation counters.                         */

#include "servers/rendering/rendering_device.h"

#include "servers/rendering/rendering_device_impl.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>

typedef RenderingDevice::Impl RDImpl;

namespace {

String lower(const String &p_s) {
	String r = p_s;
	for (char &c : r) {
		c = (char)std::tolower((unsigned char)c);
	}
	return r;
}

String version_string(uint32_t p_v) {
	return vformat("%u.%u.%u", VK_API_VERSION_MAJOR(p_v), VK_API_VERSION_MINOR(p_v), VK_API_VERSION_PATCH(p_v));
}

VKAPI_ATTR VkBool32 VKAPI_CALL debug_messenger_callback(VkDebugUtilsMessageSeverityFlagBitsEXT p_severity, VkDebugUtilsMessageTypeFlagsEXT p_type, const VkDebugUtilsMessengerCallbackDataEXT *p_data, void *p_user) {
	RDImpl *impl = (RDImpl *)p_user;
	const char *msg = (p_data && p_data->pMessage) ? p_data->pMessage : "(no message)";
	bool validation = (p_type & VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT) != 0;
	if (p_severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
		if (validation) {
			impl->validation_errors++;
		}
		ERR_PRINT(vformat("Vulkan validation error: %s", msg));
	} else if (p_severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
		if (validation) {
			impl->validation_warnings++;
		}
		WARN_PRINT(vformat("Vulkan validation warning: %s", msg));
	}
	return VK_FALSE;
}

} // namespace

static std::vector<String> pending_instance_extensions;
static std::vector<String> pending_device_extensions;

void RenderingDevice::set_extra_extensions(const std::vector<String> &p_instance_extensions, const std::vector<String> &p_device_extensions) {
	pending_instance_extensions = p_instance_extensions;
	pending_device_extensions = p_device_extensions;
}

RenderingDevice::VulkanHandles RenderingDevice::get_vulkan_handles() const {
	VulkanHandles h;
	h.instance = (void *)impl->instance;
	h.physical_device = (void *)impl->physical_device;
	h.device = (void *)impl->device;
	h.queue = (void *)impl->queue;
	h.queue_family = impl->queue_family;
	return h;
}

bool RenderingDevice::initialize(String *r_error) {
	Impl *s = impl;
	ERR_FAIL_COND_V_MSG(s->initialized, true, "RenderingDevice is already initialized.");
	String dummy;
	String &err = r_error ? *r_error : dummy;

	// Instance layers and extensions.
	const char *env_validation = getenv("GODOT_AREA_VALIDATION");
	bool want_validation = env_validation && String(env_validation) == "1";
	bool have_validation = false;
	{
		uint32_t count = 0;
		vkEnumerateInstanceLayerProperties(&count, nullptr);
		std::vector<VkLayerProperties> layers(count);
		vkEnumerateInstanceLayerProperties(&count, layers.data());
		for (const VkLayerProperties &l : layers) {
			if (strcmp(l.layerName, "VK_LAYER_KHRONOS_validation") == 0) {
				have_validation = true;
			}
		}
	}
	if (want_validation && !have_validation) {
		WARN_PRINT("GODOT_AREA_VALIDATION=1 but VK_LAYER_KHRONOS_validation is not installed (look in /usr/share/vulkan/explicit_layer.d/); continuing without validation.");
	}
	bool use_validation = want_validation && have_validation;
	s->extra_instance_extensions = pending_instance_extensions;
	s->extra_device_extensions = pending_device_extensions;
	pending_instance_extensions.clear();
	pending_device_extensions.clear();
	{
		uint32_t count = 0;
		vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr);
		std::vector<VkExtensionProperties> exts(count);
		vkEnumerateInstanceExtensionProperties(nullptr, &count, exts.data());
		for (const VkExtensionProperties &e : exts) {
			if (strcmp(e.extensionName, VK_EXT_DEBUG_UTILS_EXTENSION_NAME) == 0) {
				s->has_debug_utils = true;
			}
		}
		for (const String &wanted : s->extra_instance_extensions) {
			bool found = std::any_of(exts.begin(), exts.end(), [&](const VkExtensionProperties &e) { return wanted == e.extensionName; });
			if (!found) {
				err = vformat("The Vulkan instance extension '%s' (needed to present to a window) is not available.", wanted.c_str());
				ERR_PRINT(err);
				return false;
			}
		}
	}

	VkApplicationInfo app = { VK_STRUCTURE_TYPE_APPLICATION_INFO };
	app.pApplicationName = "godot-area";
	app.pEngineName = "godot-area";
	app.apiVersion = VK_API_VERSION_1_1;
	std::vector<const char *> layer_names;
	if (use_validation) {
		layer_names.push_back("VK_LAYER_KHRONOS_validation");
	}
	std::vector<const char *> ext_names;
	if (s->has_debug_utils) {
		ext_names.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
	}
	for (const String &e : s->extra_instance_extensions) {
		ext_names.push_back(e.c_str());
	}
	VkInstanceCreateInfo ici = { VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO };
	ici.pApplicationInfo = &app;
	ici.enabledLayerCount = (uint32_t)layer_names.size();
	ici.ppEnabledLayerNames = layer_names.data();
	ici.enabledExtensionCount = (uint32_t)ext_names.size();
	ici.ppEnabledExtensionNames = ext_names.data();
	VkResult res = vkCreateInstance(&ici, nullptr, &s->instance);
	if (res != VK_SUCCESS) {
		err = vformat("vkCreateInstance failed (VkResult %d). Is a Vulkan driver (e.g. Mesa lavapipe) installed?", res);
		s->instance = VK_NULL_HANDLE;
		ERR_PRINT(err);
		return false;
	}

	if (s->has_debug_utils) {
		s->set_object_name = (PFN_vkSetDebugUtilsObjectNameEXT)vkGetInstanceProcAddr(s->instance, "vkSetDebugUtilsObjectNameEXT");
		s->cmd_begin_label = (PFN_vkCmdBeginDebugUtilsLabelEXT)vkGetInstanceProcAddr(s->instance, "vkCmdBeginDebugUtilsLabelEXT");
		s->cmd_end_label = (PFN_vkCmdEndDebugUtilsLabelEXT)vkGetInstanceProcAddr(s->instance, "vkCmdEndDebugUtilsLabelEXT");
		auto create_messenger = (PFN_vkCreateDebugUtilsMessengerEXT)vkGetInstanceProcAddr(s->instance, "vkCreateDebugUtilsMessengerEXT");
		if (create_messenger) {
			VkDebugUtilsMessengerCreateInfoEXT mci = { VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT };
			mci.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
			// Performance hints are not requested: every image deliberately lives in GENERAL layout.
			mci.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
			mci.pfnUserCallback = debug_messenger_callback;
			mci.pUserData = s;
			create_messenger(s->instance, &mci, nullptr, &s->messenger);
		}
	}

	// Pick a physical device.
	uint32_t pd_count = 0;
	vkEnumeratePhysicalDevices(s->instance, &pd_count, nullptr);
	std::vector<VkPhysicalDevice> pds(pd_count);
	vkEnumeratePhysicalDevices(s->instance, &pd_count, pds.data());
	const char *env_device = getenv("GODOT_AREA_DEVICE");
	String forced = env_device ? String(env_device) : String();
	int best = -1;
	int best_score = -1;
	String available;
	for (uint32_t i = 0; i < pd_count; i++) {
		VkPhysicalDeviceProperties p;
		vkGetPhysicalDeviceProperties(pds[i], &p);
		available += vformat("  [%u] %s\n", i, p.deviceName);
		if (p.apiVersion < VK_API_VERSION_1_1) {
			continue;
		}
		uint32_t qf_count = 0;
		vkGetPhysicalDeviceQueueFamilyProperties(pds[i], &qf_count, nullptr);
		std::vector<VkQueueFamilyProperties> qfs(qf_count);
		vkGetPhysicalDeviceQueueFamilyProperties(pds[i], &qf_count, qfs.data());
		bool usable = false;
		for (const VkQueueFamilyProperties &q : qfs) {
			if ((q.queueFlags & VK_QUEUE_GRAPHICS_BIT) && (q.queueFlags & VK_QUEUE_COMPUTE_BIT)) {
				usable = true;
			}
		}
		if (!usable) {
			continue;
		}
		int score = 0;
		if (!forced.empty()) {
			bool numeric = std::all_of(forced.begin(), forced.end(), [](char c) { return std::isdigit((unsigned char)c); });
			bool match = numeric ? (uint32_t)atoi(forced.c_str()) == i : lower(p.deviceName).find(lower(forced)) != String::npos;
			score = match ? 100 : -1;
		} else {
			switch (p.deviceType) {
				case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
					score = 4;
					break;
				case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
					score = 3;
					break;
				case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
					score = 2;
					break;
				case VK_PHYSICAL_DEVICE_TYPE_CPU:
					score = 1;
					break;
				default:
					score = 0;
			}
		}
		if (score > best_score) {
			best_score = score;
			best = (int)i;
		}
	}
	if (best < 0) {
		err = forced.empty() ? String("No Vulkan 1.1 device with a graphics+compute queue was found.") : vformat("GODOT_AREA_DEVICE='%s' matches no usable Vulkan device. Devices:\n%s", forced.c_str(), available.c_str());
		ERR_PRINT(err);
		finalize();
		return false;
	}
	s->physical_device = pds[best];
	vkGetPhysicalDeviceProperties(s->physical_device, &s->properties);
	vkGetPhysicalDeviceMemoryProperties(s->physical_device, &s->memory_properties);

	uint32_t qf_count = 0;
	vkGetPhysicalDeviceQueueFamilyProperties(s->physical_device, &qf_count, nullptr);
	std::vector<VkQueueFamilyProperties> qfs(qf_count);
	vkGetPhysicalDeviceQueueFamilyProperties(s->physical_device, &qf_count, qfs.data());
	uint32_t timestamp_bits = 0;
	for (uint32_t i = 0; i < qf_count; i++) {
		if ((qfs[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && (qfs[i].queueFlags & VK_QUEUE_COMPUTE_BIT)) {
			s->queue_family = i;
			timestamp_bits = qfs[i].timestampValidBits;
			break;
		}
	}

	// Features: enable what we use when supported.
	VkPhysicalDeviceFeatures supported;
	vkGetPhysicalDeviceFeatures(s->physical_device, &supported);
	VkPhysicalDeviceFeatures &f = s->enabled_features;
	f.fillModeNonSolid = supported.fillModeNonSolid;
	f.depthClamp = supported.depthClamp;
	f.depthBiasClamp = supported.depthBiasClamp;
	f.independentBlend = supported.independentBlend;
	f.fragmentStoresAndAtomics = supported.fragmentStoresAndAtomics;
	f.vertexPipelineStoresAndAtomics = supported.vertexPipelineStoresAndAtomics;
	f.imageCubeArray = supported.imageCubeArray;
	f.shaderStorageImageExtendedFormats = supported.shaderStorageImageExtendedFormats;
	f.multiDrawIndirect = supported.multiDrawIndirect;
	f.drawIndirectFirstInstance = supported.drawIndirectFirstInstance;
	f.shaderSampledImageArrayDynamicIndexing = supported.shaderSampledImageArrayDynamicIndexing;
	f.shaderStorageBufferArrayDynamicIndexing = supported.shaderStorageBufferArrayDynamicIndexing;
	f.shaderImageGatherExtended = supported.shaderImageGatherExtended;
	f.largePoints = supported.largePoints;

	// Device extensions (only for driver properties).
	bool has_driver_props = false;
	{
		uint32_t count = 0;
		vkEnumerateDeviceExtensionProperties(s->physical_device, nullptr, &count, nullptr);
		std::vector<VkExtensionProperties> exts(count);
		vkEnumerateDeviceExtensionProperties(s->physical_device, nullptr, &count, exts.data());
		for (const VkExtensionProperties &e : exts) {
			if (strcmp(e.extensionName, VK_KHR_DRIVER_PROPERTIES_EXTENSION_NAME) == 0) {
				has_driver_props = true;
			}
		}
		for (const String &wanted : s->extra_device_extensions) {
			bool found = std::any_of(exts.begin(), exts.end(), [&](const VkExtensionProperties &e) { return wanted == e.extensionName; });
			if (!found) {
				err = vformat("The Vulkan device extension '%s' (needed to present to a window) is not available on '%s'.", wanted.c_str(), s->properties.deviceName);
				ERR_PRINT(err);
				finalize();
				return false;
			}
		}
	}
	std::vector<const char *> device_ext_names;
	for (const String &e : s->extra_device_extensions) {
		device_ext_names.push_back(e.c_str());
	}

	float priority = 1.0f;
	VkDeviceQueueCreateInfo qci = { VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO };
	qci.queueFamilyIndex = s->queue_family;
	qci.queueCount = 1;
	qci.pQueuePriorities = &priority;
	VkDeviceCreateInfo dci = { VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO };
	dci.queueCreateInfoCount = 1;
	dci.pQueueCreateInfos = &qci;
	dci.pEnabledFeatures = &s->enabled_features;
	dci.enabledExtensionCount = (uint32_t)device_ext_names.size();
	dci.ppEnabledExtensionNames = device_ext_names.data();
	res = vkCreateDevice(s->physical_device, &dci, nullptr, &s->device);
	if (res != VK_SUCCESS) {
		err = vformat("vkCreateDevice failed (VkResult %d) on '%s'.", res, s->properties.deviceName);
		s->device = VK_NULL_HANDLE;
		ERR_PRINT(err);
		finalize();
		return false;
	}
	vkGetDeviceQueue(s->device, s->queue_family, 0, &s->queue);

	bool timestamps = timestamp_bits > 0 && s->properties.limits.timestampPeriod > 0.0f;
	if (!s->create_frames(get_project_frame_queue_size(), timestamps)) {
		finalize();
		return false;
	}

	// Device info.
	DeviceInfo &di = s->info;
	const VkPhysicalDeviceLimits &lim = s->properties.limits;
	di.name = s->properties.deviceName;
	di.device_index = (uint32_t)best;
	di.vendor_id = s->properties.vendorID;
	di.device_id = s->properties.deviceID;
	di.driver_version = s->properties.driverVersion;
	di.api_version = version_string(s->properties.apiVersion);
	switch (s->properties.deviceType) {
		case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
			di.type = DEVICE_TYPE_DISCRETE_GPU;
			di.type_name = "discrete GPU";
			break;
		case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
			di.type = DEVICE_TYPE_INTEGRATED_GPU;
			di.type_name = "integrated GPU";
			break;
		case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
			di.type = DEVICE_TYPE_VIRTUAL_GPU;
			di.type_name = "virtual GPU";
			break;
		case VK_PHYSICAL_DEVICE_TYPE_CPU:
			di.type = DEVICE_TYPE_CPU;
			di.type_name = "CPU";
			break;
		default:
			di.type = DEVICE_TYPE_OTHER;
			di.type_name = "other";
	}
	if (has_driver_props) {
		VkPhysicalDeviceDriverPropertiesKHR dp = { VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES_KHR };
		VkPhysicalDeviceProperties2 p2 = { VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2 };
		p2.pNext = &dp;
		vkGetPhysicalDeviceProperties2(s->physical_device, &p2);
		di.driver_name = dp.driverName;
		di.driver_info = dp.driverInfo;
	} else {
		di.driver_name = "unknown";
	}
	di.validation_enabled = use_validation;
	di.debug_utils_enabled = s->has_debug_utils;
	di.timestamps_supported = timestamps;
	di.timestamp_period_ns = lim.timestampPeriod;
	di.max_texture_size_2d = lim.maxImageDimension2D;
	di.max_texture_array_layers = lim.maxImageArrayLayers;
	di.max_push_constant_size = lim.maxPushConstantsSize;
	di.max_uniform_buffer_size = lim.maxUniformBufferRange;
	di.max_storage_buffer_size = lim.maxStorageBufferRange;
	di.max_bound_descriptor_sets = lim.maxBoundDescriptorSets;
	di.max_color_attachments = lim.maxColorAttachments;
	for (int i = 0; i < 3; i++) {
		di.max_compute_workgroup_count[i] = lim.maxComputeWorkGroupCount[i];
		di.max_compute_workgroup_size[i] = lim.maxComputeWorkGroupSize[i];
	}
	di.max_compute_workgroup_invocations = lim.maxComputeWorkGroupInvocations;
	di.min_uniform_buffer_offset_alignment = (uint32_t)lim.minUniformBufferOffsetAlignment;
	di.min_storage_buffer_offset_alignment = (uint32_t)lim.minStorageBufferOffsetAlignment;
	for (uint32_t i = 0; i < s->memory_properties.memoryHeapCount; i++) {
		if (s->memory_properties.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) {
			di.device_local_memory = std::max<uint64_t>(di.device_local_memory, s->memory_properties.memoryHeaps[i].size);
		}
	}

	s->initialized = true;
	s->begin_frame();
	return true;
}

void RenderingDevice::finalize() {
	Impl *s = impl;
	if (s->device) {
		if (s->recording && !s->list.active && s->command_buffer) {
			vkEndCommandBuffer(s->command_buffer);
			s->recording = false;
		}
		vkDeviceWaitIdle(s->device);
		s->submitted = false;
		s->destroy_frames(); // Runs the deferred frees; async readbacks are dropped.
		for (Impl::Staging &st : s->readback_pool) {
			destroy_staging(s->device, st);
		}
		s->readback_pool.clear();

		// Destroy what the user did not free; the RIDs stay in their owners and are reported as leaks.
		VkDevice dev = s->device;
		for (RID r : s->pipeline_owner.get_owned_list()) {
			vkDestroyPipeline(dev, s->pipeline_owner.get_or_null(r)->pipeline, nullptr);
		}
		for (RID r : s->uniform_set_owner.get_owned_list()) {
			vkDestroyDescriptorPool(dev, s->uniform_set_owner.get_or_null(r)->pool, nullptr);
		}
		for (RID r : s->framebuffer_owner.get_owned_list()) {
			vkDestroyFramebuffer(dev, s->framebuffer_owner.get_or_null(r)->framebuffer, nullptr);
		}
		for (RID r : s->shader_owner.get_owned_list()) {
			Impl::Shader *sh = s->shader_owner.get_or_null(r);
			for (VkShaderModule m : sh->modules) {
				if (m) {
					vkDestroyShaderModule(dev, m, nullptr);
				}
			}
			vkDestroyPipelineLayout(dev, sh->pipeline_layout, nullptr);
		}
		for (RID r : s->sampler_owner.get_owned_list()) {
			vkDestroySampler(dev, s->sampler_owner.get_or_null(r)->sampler, nullptr);
		}
		std::vector<RID> textures = s->texture_owner.get_owned_list();
		for (RID r : textures) {
			Impl::Texture *t = s->texture_owner.get_or_null(r);
			vkDestroyImageView(dev, t->view, nullptr);
		}
		for (RID r : textures) {
			Impl::Texture *t = s->texture_owner.get_or_null(r);
			if (!t->is_slice) {
				vkDestroyImage(dev, t->image, nullptr);
				vkFreeMemory(dev, t->memory, nullptr);
			}
		}
		for (RID r : s->buffer_owner.get_owned_list()) {
			Impl::Buffer *b = s->buffer_owner.get_or_null(r);
			vkDestroyBuffer(dev, b->buffer, nullptr);
			vkFreeMemory(dev, b->memory, nullptr);
		}
		for (Impl::FramebufferFormat &ff : s->framebuffer_formats) {
			for (int i = 0; i < 3; i++) {
				for (int j = 0; j < 3; j++) {
					if (ff.passes[i][j]) {
						vkDestroyRenderPass(dev, ff.passes[i][j], nullptr);
					}
				}
			}
		}
		for (auto &kv : s->set_layout_cache) {
			vkDestroyDescriptorSetLayout(dev, kv.second, nullptr);
		}
		vkDestroyDevice(dev, nullptr);
	}
	if (s->messenger) {
		auto destroy_messenger = (PFN_vkDestroyDebugUtilsMessengerEXT)vkGetInstanceProcAddr(s->instance, "vkDestroyDebugUtilsMessengerEXT");
		if (destroy_messenger) {
			destroy_messenger(s->instance, s->messenger, nullptr);
		}
	}
	if (s->instance) {
		vkDestroyInstance(s->instance, nullptr);
	}
	// Deleting the state reports leaked RIDs (RID_Owner destructors).
	delete s;
	impl = new Impl;
}

const RenderingDevice::DeviceInfo &RenderingDevice::get_device_info() const {
	return impl->info;
}

String RenderingDevice::get_device_info_string() const {
	const DeviceInfo &d = impl->info;
	if (!impl->initialized) {
		return "RenderingDevice: not initialized.\n";
	}
	String s;
	s += vformat("Device: %s (index %u)\n", d.name.c_str(), d.device_index);
	s += vformat("Type: %s\n", d.type_name.c_str());
	s += vformat("Vendor ID: 0x%04x  Device ID: 0x%04x\n", d.vendor_id, d.device_id);
	s += vformat("Driver: %s %s (version 0x%08x)\n", d.driver_name.c_str(), d.driver_info.c_str(), d.driver_version);
	s += vformat("Vulkan API: %s (engine targets 1.1)\n", d.api_version.c_str());
	s += vformat("Validation layer: %s  Debug utils: %s\n", d.validation_enabled ? "on" : "off", d.debug_utils_enabled ? "yes" : "no");
	s += vformat("Timestamps: %s (period %.3f ns)\n", d.timestamps_supported ? "yes" : "no", d.timestamp_period_ns);
	s += vformat("Max 2D texture size: %u  Max array layers: %u\n", d.max_texture_size_2d, d.max_texture_array_layers);
	s += vformat("Max push constants: %u bytes  Max UBO range: %u  Max SSBO range: %u\n", d.max_push_constant_size, d.max_uniform_buffer_size, d.max_storage_buffer_size);
	s += vformat("Max bound descriptor sets: %u  Max colour attachments: %u\n", d.max_bound_descriptor_sets, d.max_color_attachments);
	s += vformat("Max compute work groups: %u x %u x %u, size %u x %u x %u, invocations %u\n", d.max_compute_workgroup_count[0], d.max_compute_workgroup_count[1], d.max_compute_workgroup_count[2], d.max_compute_workgroup_size[0], d.max_compute_workgroup_size[1], d.max_compute_workgroup_size[2], d.max_compute_workgroup_invocations);
	s += vformat("Device-local memory: %llu MiB\n", (unsigned long long)(d.device_local_memory / (1024 * 1024)));
	return s;
}

uint32_t RenderingDevice::get_validation_error_count() const {
	return impl->validation_errors;
}

uint32_t RenderingDevice::get_validation_warning_count() const {
	return impl->validation_warnings;
}

void RenderingDevice::reset_validation_counts() {
	impl->validation_errors = 0;
	impl->validation_warnings = 0;
}

uint64_t RenderingDevice::get_frames_submitted() const {
	return impl->frames_submitted;
}
