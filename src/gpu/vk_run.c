/*
 * vk_run.c - one dispatch of one SPIR-V kernel (vk.h, gpu_run): two
 * storage buffers, a pipeline whose specialization constant 0 selects the
 * kernel, one command buffer, a fence.  Every object is made and
 * destroyed per run: a run is one kernel over a whole input set, so the
 * cost is the driver's compile, not these calls.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vulkan/vulkan.h>
#include "gpu/vk.h"
#include "gpu/vk_int.h"

typedef struct {
	VkBuffer buf[2];
	VkDeviceMemory mem[2];
	VkShaderModule mod;
	VkDescriptorSetLayout dsl;
	VkPipelineLayout pl;
	VkPipeline pipe;
	VkDescriptorPool pool;
	VkCommandPool cpool;
	VkFence fence;
} run_objs;

static int fail(const char *what, VkResult r)
{
	fprintf(stderr, "onbstudy-gpu: %s failed (VkResult %d)\n", what, (int)r);
	return -1;
}

static uint32_t *read_spv(const char *path, size_t *bytes)
{
	FILE *f = fopen(path, "rb");
	uint32_t *w = NULL;
	long n;
	if (!f) {
		fprintf(stderr, "onbstudy-gpu: cannot open %s (make gpu builds the SPIR-V)\n", path);
		return NULL;
	}
	if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) > 0 && n % 4 == 0 && fseek(f, 0, SEEK_SET) == 0
	    && (w = malloc((size_t)n)) != NULL && fread(w, 1, (size_t)n, f) == (size_t)n) {
		*bytes = (size_t)n;
	} else {
		fprintf(stderr, "onbstudy-gpu: %s is not a readable SPIR-V file\n", path);
		free(w);
		w = NULL;
	}
	fclose(f);
	return w;
}

static int make_buffer(gpu_dev *d, size_t bytes, VkBuffer *b, VkDeviceMemory *m)
{
	VkBufferCreateInfo bi;
	VkMemoryRequirements req;
	VkMemoryAllocateInfo ai;
	const VkPhysicalDeviceMemoryProperties *mp = gpu__mem(d);
	const VkMemoryPropertyFlags want = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
	uint32_t t;
	VkResult r;
	memset(&bi, 0, sizeof bi);
	bi.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
	bi.size = bytes;
	bi.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
	bi.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
	if ((r = vkCreateBuffer(gpu__dev(d), &bi, NULL, b)) != VK_SUCCESS)
		return fail("vkCreateBuffer", r);
	vkGetBufferMemoryRequirements(gpu__dev(d), *b, &req);
	for (t = 0; t < mp->memoryTypeCount; t++)
		if ((req.memoryTypeBits >> t & 1u) && (mp->memoryTypes[t].propertyFlags & want) == want)
			break;
	if (t == mp->memoryTypeCount) {
		fprintf(stderr, "onbstudy-gpu: no host-visible coherent memory\n");
		return -1;
	}
	memset(&ai, 0, sizeof ai);
	ai.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
	ai.allocationSize = req.size;
	ai.memoryTypeIndex = t;
	if ((r = vkAllocateMemory(gpu__dev(d), &ai, NULL, m)) != VK_SUCCESS)
		return fail("vkAllocateMemory", r);
	if ((r = vkBindBufferMemory(gpu__dev(d), *b, *m, 0)) != VK_SUCCESS)
		return fail("vkBindBufferMemory", r);
	return 0;
}

static int copy_in(gpu_dev *d, VkDeviceMemory m, const void *src, size_t bytes)
{
	void *p;
	VkResult r = vkMapMemory(gpu__dev(d), m, 0, VK_WHOLE_SIZE, 0, &p);
	if (r != VK_SUCCESS)
		return fail("vkMapMemory", r);
	if (src)
		memcpy(p, src, bytes);
	else
		memset(p, 0xff, bytes);  /* out: NaN bits, so an unwritten word shows */
	vkUnmapMemory(gpu__dev(d), m);
	return 0;
}

static int make_layout(gpu_dev *d, run_objs *o)
{
	VkDescriptorSetLayoutBinding lb[2];
	VkDescriptorSetLayoutCreateInfo li;
	VkPipelineLayoutCreateInfo pi;
	VkResult r;
	int i;
	memset(lb, 0, sizeof lb);
	for (i = 0; i < 2; i++) {
		lb[i].binding = (uint32_t)i;
		lb[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
		lb[i].descriptorCount = 1;
		lb[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
	}
	memset(&li, 0, sizeof li);
	li.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
	li.bindingCount = 2;
	li.pBindings = lb;
	if ((r = vkCreateDescriptorSetLayout(gpu__dev(d), &li, NULL, &o->dsl)) != VK_SUCCESS)
		return fail("vkCreateDescriptorSetLayout", r);
	memset(&pi, 0, sizeof pi);
	pi.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
	pi.setLayoutCount = 1;
	pi.pSetLayouts = &o->dsl;
	if ((r = vkCreatePipelineLayout(gpu__dev(d), &pi, NULL, &o->pl)) != VK_SUCCESS)
		return fail("vkCreatePipelineLayout", r);
	return 0;
}

static int make_pipeline(gpu_dev *d, run_objs *o, const char *spv, int32_t kernel)
{
	VkShaderModuleCreateInfo mi;
	VkSpecializationMapEntry me;
	VkSpecializationInfo si;
	VkComputePipelineCreateInfo ci;
	size_t bytes = 0;
	uint32_t *code = read_spv(spv, &bytes);
	VkResult r;
	if (!code)
		return -1;
	memset(&mi, 0, sizeof mi);
	mi.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
	mi.codeSize = bytes;
	mi.pCode = code;
	r = vkCreateShaderModule(gpu__dev(d), &mi, NULL, &o->mod);
	free(code);
	if (r != VK_SUCCESS)
		return fail("vkCreateShaderModule", r);
	me.constantID = 0;
	me.offset = 0;
	me.size = sizeof kernel;
	si.mapEntryCount = 1;
	si.pMapEntries = &me;
	si.dataSize = sizeof kernel;
	si.pData = &kernel;
	memset(&ci, 0, sizeof ci);
	ci.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
	ci.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
	ci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
	ci.stage.module = o->mod;
	ci.stage.pName = "main";
	ci.stage.pSpecializationInfo = &si;
	ci.layout = o->pl;
	if ((r = vkCreateComputePipelines(gpu__dev(d), VK_NULL_HANDLE, 1, &ci, NULL, &o->pipe)) != VK_SUCCESS)
		return fail("vkCreateComputePipelines", r);
	return 0;
}

static int bind_set(gpu_dev *d, run_objs *o, VkDescriptorSet *set)
{
	VkDescriptorPoolSize ps;
	VkDescriptorPoolCreateInfo pi;
	VkDescriptorSetAllocateInfo ai;
	VkDescriptorBufferInfo bi[2];
	VkWriteDescriptorSet w[2];
	VkResult r;
	int i;
	ps.type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
	ps.descriptorCount = 2;
	memset(&pi, 0, sizeof pi);
	pi.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
	pi.maxSets = 1;
	pi.poolSizeCount = 1;
	pi.pPoolSizes = &ps;
	if ((r = vkCreateDescriptorPool(gpu__dev(d), &pi, NULL, &o->pool)) != VK_SUCCESS)
		return fail("vkCreateDescriptorPool", r);
	memset(&ai, 0, sizeof ai);
	ai.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
	ai.descriptorPool = o->pool;
	ai.descriptorSetCount = 1;
	ai.pSetLayouts = &o->dsl;
	if ((r = vkAllocateDescriptorSets(gpu__dev(d), &ai, set)) != VK_SUCCESS)
		return fail("vkAllocateDescriptorSets", r);
	memset(w, 0, sizeof w);
	for (i = 0; i < 2; i++) {
		bi[i].buffer = o->buf[i];
		bi[i].offset = 0;
		bi[i].range = VK_WHOLE_SIZE;
		w[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
		w[i].dstSet = *set;
		w[i].dstBinding = (uint32_t)i;
		w[i].descriptorCount = 1;
		w[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
		w[i].pBufferInfo = &bi[i];
	}
	vkUpdateDescriptorSets(gpu__dev(d), 2, w, 0, NULL);
	return 0;
}

static int submit(gpu_dev *d, run_objs *o, VkDescriptorSet set, uint32_t groups)
{
	VkCommandPoolCreateInfo pi;
	VkCommandBufferAllocateInfo ai;
	VkCommandBufferBeginInfo bi;
	VkSubmitInfo si;
	VkFenceCreateInfo fi;
	VkCommandBuffer cb;
	VkResult r;
	memset(&pi, 0, sizeof pi);
	pi.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
	pi.queueFamilyIndex = gpu__qfam(d);
	if ((r = vkCreateCommandPool(gpu__dev(d), &pi, NULL, &o->cpool)) != VK_SUCCESS)
		return fail("vkCreateCommandPool", r);
	memset(&ai, 0, sizeof ai);
	ai.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
	ai.commandPool = o->cpool;
	ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
	ai.commandBufferCount = 1;
	if ((r = vkAllocateCommandBuffers(gpu__dev(d), &ai, &cb)) != VK_SUCCESS)
		return fail("vkAllocateCommandBuffers", r);
	memset(&bi, 0, sizeof bi);
	bi.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
	bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
	vkBeginCommandBuffer(cb, &bi);
	vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, o->pipe);
	vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, o->pl, 0, 1, &set, 0, NULL);
	vkCmdDispatch(cb, groups, 1, 1);
	if ((r = vkEndCommandBuffer(cb)) != VK_SUCCESS)
		return fail("vkEndCommandBuffer", r);
	memset(&fi, 0, sizeof fi);
	fi.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
	if ((r = vkCreateFence(gpu__dev(d), &fi, NULL, &o->fence)) != VK_SUCCESS)
		return fail("vkCreateFence", r);
	memset(&si, 0, sizeof si);
	si.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
	si.commandBufferCount = 1;
	si.pCommandBuffers = &cb;
	if ((r = vkQueueSubmit(gpu__queue(d), 1, &si, o->fence)) != VK_SUCCESS)
		return fail("vkQueueSubmit", r);
	if ((r = vkWaitForFences(gpu__dev(d), 1, &o->fence, VK_TRUE, UINT64_MAX)) != VK_SUCCESS)
		return fail("vkWaitForFences", r);
	return 0;
}

static int copy_out(gpu_dev *d, VkDeviceMemory m, void *dst, size_t bytes)
{
	void *p;
	VkResult r = vkMapMemory(gpu__dev(d), m, 0, VK_WHOLE_SIZE, 0, &p);
	if (r != VK_SUCCESS)
		return fail("vkMapMemory", r);
	memcpy(dst, p, bytes);
	vkUnmapMemory(gpu__dev(d), m);
	return 0;
}

static void destroy(gpu_dev *d, run_objs *o)
{
	VkDevice v = gpu__dev(d);
	int i;
	vkDeviceWaitIdle(v);
	vkDestroyFence(v, o->fence, NULL);
	vkDestroyCommandPool(v, o->cpool, NULL);
	vkDestroyDescriptorPool(v, o->pool, NULL);
	vkDestroyPipeline(v, o->pipe, NULL);
	vkDestroyPipelineLayout(v, o->pl, NULL);
	vkDestroyDescriptorSetLayout(v, o->dsl, NULL);
	vkDestroyShaderModule(v, o->mod, NULL);
	for (i = 0; i < 2; i++) {
		vkDestroyBuffer(v, o->buf[i], NULL);
		vkFreeMemory(v, o->mem[i], NULL);
	}
}

int gpu_run(gpu_dev *d, const char *spv, int32_t kernel,
            const uint32_t *in, size_t in_words, uint32_t *out, size_t out_words,
            uint32_t groups)
{
	run_objs o;
	VkDescriptorSet set;
	const size_t ib = in_words * 4, ob = out_words * 4;
	int rc = -1;
	memset(&o, 0, sizeof o);
	if (make_buffer(d, ib, &o.buf[0], &o.mem[0]) == 0 && make_buffer(d, ob, &o.buf[1], &o.mem[1]) == 0
	    && copy_in(d, o.mem[0], in, ib) == 0 && copy_in(d, o.mem[1], NULL, ob) == 0
	    && make_layout(d, &o) == 0 && make_pipeline(d, &o, spv, kernel) == 0
	    && bind_set(d, &o, &set) == 0 && submit(d, &o, set, groups) == 0
	    && copy_out(d, o.mem[1], out, ob) == 0)
		rc = 0;
	destroy(d, &o);
	return rc;
}
