/*
 * vk.c - the Vulkan compute harness of onbstudy-gpu (vk.h).  Plain Vulkan
 * 1.1: host-visible, coherent buffers (lavapipe's memory is the host's),
 * one pipeline per run, a fence to wait on.  No validation layers: the
 * harness is small enough to read, and tests/gpu.sh runs it under the
 * sanitizers.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vulkan/vulkan.h>
#include "gpu/vk.h"
#include "gpu/vk_int.h"

struct gpu_dev {
	VkInstance inst;
	VkPhysicalDevice phys;
	VkDevice dev;
	VkQueue queue;
	uint32_t qfam;
	VkPhysicalDeviceMemoryProperties mem;
	VkPhysicalDeviceProperties props;
	VkPhysicalDeviceDriverProperties drv;
	char controls[512];
	int f64, f16;
};

static int vk_fail(const char *what, VkResult r)
{
	fprintf(stderr, "onbstudy-gpu: %s failed (VkResult %d)\n", what, (int)r);
	return -1;
}

static VkPhysicalDevice pick(VkInstance inst, const char *want)
{
	VkPhysicalDevice list[16], hit = VK_NULL_HANDLE;
	uint32_t n = 16, i;
	VkResult r = vkEnumeratePhysicalDevices(inst, &n, list);
	if (r != VK_SUCCESS && r != VK_INCOMPLETE) {
		vk_fail("vkEnumeratePhysicalDevices", r);
		return VK_NULL_HANDLE;
	}
	for (i = 0; i < n && hit == VK_NULL_HANDLE; i++) {
		VkPhysicalDeviceProperties p;
		vkGetPhysicalDeviceProperties(list[i], &p);
		if (strstr(p.deviceName, want))
			hit = list[i];
	}
	if (hit == VK_NULL_HANDLE) {
		fprintf(stderr, "onbstudy-gpu: no Vulkan device named like \"%s\" among %u:", want, n);
		for (i = 0; i < n; i++) {
			VkPhysicalDeviceProperties p;
			vkGetPhysicalDeviceProperties(list[i], &p);
			fprintf(stderr, " \"%s\"", p.deviceName);
		}
		fprintf(stderr, "%s\n", want[0] ? " (lavapipe: scripts/install-deps.sh --test installs mesa-vulkan-drivers)" : "");
	}
	return hit;
}

static void describe(gpu_dev *d)
{
	VkPhysicalDeviceFloatControlsProperties fc;
	VkPhysicalDeviceProperties2 p2;
	memset(&fc, 0, sizeof fc);
	memset(&d->drv, 0, sizeof d->drv);
	fc.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FLOAT_CONTROLS_PROPERTIES;
	d->drv.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES;
	d->drv.pNext = &fc;
	memset(&p2, 0, sizeof p2);
	p2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
	p2.pNext = &d->drv;
	vkGetPhysicalDeviceProperties2(d->phys, &p2);
	d->props = p2.properties;
	snprintf(d->controls, sizeof d->controls,
	         "float32: denorm preserve %u, denorm flush-to-zero %u, signed zero/inf/nan preserve %u, rounding RTE %u, RTZ %u",
	         (unsigned)fc.shaderDenormPreserveFloat32, (unsigned)fc.shaderDenormFlushToZeroFloat32,
	         (unsigned)fc.shaderSignedZeroInfNanPreserveFloat32, (unsigned)fc.shaderRoundingModeRTEFloat32,
	         (unsigned)fc.shaderRoundingModeRTZFloat32);
	snprintf(d->controls + strlen(d->controls), sizeof d->controls - strlen(d->controls),
	         "; float16: denorm preserve %u, denorm flush-to-zero %u, signed zero/inf/nan preserve %u, rounding RTE %u, RTZ %u",
	         (unsigned)fc.shaderDenormPreserveFloat16, (unsigned)fc.shaderDenormFlushToZeroFloat16,
	         (unsigned)fc.shaderSignedZeroInfNanPreserveFloat16, (unsigned)fc.shaderRoundingModeRTEFloat16,
	         (unsigned)fc.shaderRoundingModeRTZFloat16);
	vkGetPhysicalDeviceMemoryProperties(d->phys, &d->mem);
}

static int make_device(gpu_dev *d)
{
	VkQueueFamilyProperties qf[16];
	uint32_t nq = 16, i;
	float prio = 1.0f;
	VkDeviceQueueCreateInfo qi;
	VkDeviceCreateInfo di;
	VkPhysicalDeviceFeatures have, use;
	VkPhysicalDeviceShaderFloat16Int8Features h16, u16;
	VkPhysicalDeviceFeatures2 f2;
	VkResult r;
	vkGetPhysicalDeviceQueueFamilyProperties(d->phys, &nq, qf);
	for (i = 0; i < nq && !(qf[i].queueFlags & VK_QUEUE_COMPUTE_BIT); i++)
		;
	if (i == nq) {
		fprintf(stderr, "onbstudy-gpu: device \"%s\" has no compute queue\n", d->props.deviceName);
		return -1;
	}
	d->qfam = i;
	vkGetPhysicalDeviceFeatures(d->phys, &have);
	memset(&use, 0, sizeof use);
	use.shaderFloat64 = have.shaderFloat64;  /* the kernels that widen to double */
	d->f64 = have.shaderFloat64 == VK_TRUE;
	/* binary16 arithmetic (onbstudy-gpu half): shaderFloat16, core in 1.2 */
	memset(&h16, 0, sizeof h16);
	h16.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES;
	memset(&f2, 0, sizeof f2);
	f2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
	f2.pNext = &h16;
	if (d->props.apiVersion >= VK_API_VERSION_1_2)
		vkGetPhysicalDeviceFeatures2(d->phys, &f2);
	d->f16 = h16.shaderFloat16 == VK_TRUE;
	memset(&u16, 0, sizeof u16);
	u16.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES;
	u16.shaderFloat16 = h16.shaderFloat16;
	memset(&qi, 0, sizeof qi);
	qi.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
	qi.queueFamilyIndex = d->qfam;
	qi.queueCount = 1;
	qi.pQueuePriorities = &prio;
	memset(&di, 0, sizeof di);
	di.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
	di.queueCreateInfoCount = 1;
	di.pQueueCreateInfos = &qi;
	di.pEnabledFeatures = &use;
	if (d->f16)
		di.pNext = &u16;
	r = vkCreateDevice(d->phys, &di, NULL, &d->dev);
	if (r != VK_SUCCESS)
		return vk_fail("vkCreateDevice", r);
	vkGetDeviceQueue(d->dev, d->qfam, 0, &d->queue);
	return 0;
}

gpu_dev *gpu_open(const char *want)
{
	VkApplicationInfo app;
	VkInstanceCreateInfo ii;
	VkResult r;
	gpu_dev *d = calloc(1, sizeof *d);
	if (!d) {
		fprintf(stderr, "onbstudy-gpu: out of memory\n");
		return NULL;
	}
	memset(&app, 0, sizeof app);
	app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
	app.pApplicationName = "onbstudy-gpu";
	app.apiVersion = VK_API_VERSION_1_2;
	memset(&ii, 0, sizeof ii);
	ii.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
	ii.pApplicationInfo = &app;
	r = vkCreateInstance(&ii, NULL, &d->inst);
	if (r != VK_SUCCESS) {
		vk_fail("vkCreateInstance (is a Vulkan driver installed? lavapipe: scripts/install-deps.sh --test)", r);
		free(d);
		return NULL;
	}
	d->phys = pick(d->inst, want);
	if (d->phys == VK_NULL_HANDLE) {
		vkDestroyInstance(d->inst, NULL);
		free(d);
		return NULL;
	}
	describe(d);
	if (make_device(d) != 0) {
		vkDestroyInstance(d->inst, NULL);
		free(d);
		return NULL;
	}
	return d;
}

void gpu_close(gpu_dev *d)
{
	if (!d)
		return;
	vkDestroyDevice(d->dev, NULL);
	vkDestroyInstance(d->inst, NULL);
	free(d);
}

const char *gpu_name(const gpu_dev *d) { return d->props.deviceName; }
const char *gpu_driver(const gpu_dev *d) { return d->drv.driverInfo; }
uint32_t gpu_api(const gpu_dev *d) { return d->props.apiVersion; }
int gpu_float64(const gpu_dev *d) { return d->f64; }
int gpu_float16(const gpu_dev *d) { return d->f16; }
const char *gpu_float_controls(const gpu_dev *d) { return d->controls; }

VkDevice gpu__dev(const gpu_dev *d) { return d->dev; }
VkQueue gpu__queue(const gpu_dev *d) { return d->queue; }
uint32_t gpu__qfam(const gpu_dev *d) { return d->qfam; }
const VkPhysicalDeviceMemoryProperties *gpu__mem(const gpu_dev *d) { return &d->mem; }
