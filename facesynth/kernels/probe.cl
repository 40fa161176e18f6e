// The device probe: kernels that use what facesynth's kernels use (float8 arithmetic, integer
// atomics on global memory, reinterpretation of float bits, correctly rounded sqrt). A device is
// used only if this builds and returns the expected numbers.
#pragma OPENCL FP_CONTRACT OFF

__kernel void probe(__global const float *x, __global float *y, __global int *low)
{
    const int i = get_global_id(0);
    const float8 v = (float8)(x[i]) * (float8)(1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f, 8.0f);
    y[i] = v.s0 + v.s1 + v.s2 + v.s3 + v.s4 + v.s5 + v.s6 + v.s7;   // 36 x[i]
    atomic_min(low, as_int(x[i]));
}

__kernel void probe_sqrt(__global const float *x, __global float *y)
{
    const int i = get_global_id(0);
    y[i] = sqrt(x[i]);
}
