// FlightKernel, part: RK4's step (Rk4), which picks the shape: the unrolled form (Rk4Unrolled), the loop over the stages
// (Rk4Loop), or a straight-line form (FlightKernel.Rk4Straight.cs). Each shape
// gives the same bits. The kernel's entry points (RungeKutta4, RungeKutta4Advance) are in FlightKernel.cs; the rates in
// FlightKernel.Rates.cs.
using System.Runtime.CompilerServices;
using MagnusBall.Aerodynamics;

namespace MagnusBall.Integration.Kernels
{
    internal sealed partial class FlightKernel<TDrag, TLift, TDecay>
    {
        // One RK4 step, RungeKutta4.Step's arithmetic term by term, plus the end rates, in one of two shapes with the same
        // arithmetic. The stage positions are formed only when the wind depends on the height (no law reads the position
        // otherwise), the stage spins only when the spin decays (otherwise its rate is zero and every stage spin equals the
        // start spin). The velocities, on the dependent chain from one stage's slope to the next, are kept component by
        // component so that the chain stays in registers.
        // - Laws that read no spin parameter (the folded form: constant coefficients, or none): the four evaluations
        //   written out (Rk4Unrolled). Their evaluation is a dozen operations, so four copies are small, and straight-line
        //   code lets the JIT keep the chain in registers (the loop spilled each stage's slope to the stack and reloaded
        //   it: 0.86x against 0.74x the thesis-style step, ratios in one run, docs/performance.md).
        // - Every other kernel: one evaluation site, a loop over the four evaluations k2, k3, k4 and the end (Rk4Loop), so
        //   the inlined laws appear once in the code (four inlined copies of Stepanek's laws made a 6 kB method with a
        //   1.6 kB stack frame, and were measured slower).
        // - Under Mono, the thesis model's common case first takes the straight-line form (Rk4Straight), here rather than
        //   inside Rk4Unrolled, whose large frame Mono zeroes on every call; and Stepanek's tennis laws folded in still air
        //   take theirs (Rk4StraightStepanek) before Rk4Loop. A straight-line form that declines leaves end untouched (its
        //   caller may pass k1 as end), and Rk4Loop or Rk4Unrolled takes the step.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private void Rk4(in FlightState state, in StateDerivative k1, double step, out FlightState next, out StateDerivative end)
        {
            if ((_drag.Reads | _lift.Reads | _decay.Reads) != AeroInputs.None)
            {
                if (PreferStraightLine && StepanekStraightCase && Counter is null &&
                    Rk4StraightStepanek(state, k1, step, out next, out Vector3d straightAcceleration, out Vector3d straightSpinAcceleration))
                {
                    end = new StateDerivative(next.Velocity, straightAcceleration, straightSpinAcceleration);
                    return;
                }

                Rk4Loop(state, k1, step, out next, out end);
                return;
            }

            if (PreferStraightLine && StraightLineCase && Counter is null && Rk4Straight(state, k1, step, out next, out Vector3d endAcceleration))
            {
                end = new StateDerivative(next.Velocity, endAcceleration, default);
                return;
            }

            Rk4Unrolled(state, k1, step, out next, out end);
        }

        private void Rk4Unrolled(in FlightState state, in StateDerivative k1, double step, out FlightState next, out StateDerivative end)
        {
            double half = 0.5 * step;
            double sixth = step / 6.0;
            bool spins = _decay.IsPresent;
            bool positions = _windVaries;
            Vector3d p = state.Position, w = state.AngularVelocity;
            double vx = state.Velocity.X, vy = state.Velocity.Y, vz = state.Velocity.Z;
            Vector3d k1a = k1.Acceleration, k1s = k1.AngularAcceleration;
            SpinRates(w.X, w.Y, w.Z, out double spinRate, out double inverseSpinRate); // the whole step's, when the spin is constant

            // k2 at y + h/2 k1
            double v2x = vx + half * k1a.X, v2y = vy + half * k1a.Y, v2z = vz + half * k1a.Z;
            Vector3d w2 = spins ? Add(w, k1s, half) : w;
            Vector3d p2 = positions ? new Vector3d(p.X + half * vx, p.Y + half * vy, p.Z + half * vz) : p;
            Stage(p2, v2x, v2y, v2z, w2, ref spinRate, ref inverseSpinRate, out Vector3d a2, out Vector3d s2);

            // k3 at y + h/2 k2
            double v3x = vx + half * a2.X, v3y = vy + half * a2.Y, v3z = vz + half * a2.Z;
            Vector3d w3 = spins ? Add(w, s2, half) : w;
            Vector3d p3 = positions ? new Vector3d(p.X + half * v2x, p.Y + half * v2y, p.Z + half * v2z) : p;
            Stage(p3, v3x, v3y, v3z, w3, ref spinRate, ref inverseSpinRate, out Vector3d a3, out Vector3d s3);

            // k4 at y + h k3
            double v4x = vx + step * a3.X, v4y = vy + step * a3.Y, v4z = vz + step * a3.Z;
            Vector3d w4 = spins ? Add(w, s3, step) : w;
            Vector3d p4 = positions ? new Vector3d(p.X + step * v3x, p.Y + step * v3y, p.Z + step * v3z) : p;
            Stage(p4, v4x, v4y, v4z, w4, ref spinRate, ref inverseSpinRate, out Vector3d a4, out Vector3d s4);

            // y + (k1 + 2 (k2 + k3) + k4) h/6, grouped as RungeKutta4 groups it, and the end rates
            Vector3d k1v = k1.Velocity;
            Vector3d pe = EndPosition(p, k1v, v2x, v2y, v2z, v3x, v3y, v3z, v4x, v4y, v4z, sixth);
            double vex = vx + (k1a.X + (a2.X + a3.X) * 2.0 + a4.X) * sixth;
            double vey = vy + (k1a.Y + (a2.Y + a3.Y) * 2.0 + a4.Y) * sixth;
            double vez = vz + (k1a.Z + (a2.Z + a3.Z) * 2.0 + a4.Z) * sixth;
            Vector3d we = spins ? w + (k1s + 2.0 * (s2 + s3) + s4) * sixth : w + k1s * sixth;
            double time = state.Time + step;
            Stage(pe, vex, vey, vez, we, ref spinRate, ref inverseSpinRate, out Vector3d endAcceleration, out Vector3d endSpinAcceleration);
            var ve = new Vector3d(vex, vey, vez);
            next = new FlightState(pe, ve, we, time);
            end = new StateDerivative(ve, endAcceleration, endSpinAcceleration);
        }

        // The end position y + (k1 + 2 (k2 + k3) + k4) h/6 from the stage velocities, grouped as RungeKutta4 groups it (the
        // written-out steps' common tail: Rk4Unrolled, Rk4Straight, Rk4StraightStepanek).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3d EndPosition(
            in Vector3d p, in Vector3d k1v, double v2x, double v2y, double v2z, double v3x, double v3y, double v3z,
            double v4x, double v4y, double v4z, double sixth) =>
            new Vector3d(
                p.X + (k1v.X + (v2x + v3x) * 2.0 + v4x) * sixth,
                p.Y + (k1v.Y + (v2y + v3y) * 2.0 + v4y) * sixth,
                p.Z + (k1v.Z + (v2z + v3z) * 2.0 + v4z) * sixth);

        // k2 + k3 is summed as soon as k3 is known (the same sum RungeKutta4 forms, fewer numbers live across the loop).
        private void Rk4Loop(in FlightState state, in StateDerivative k1, double step, out FlightState next, out StateDerivative end)
        {
            double half = 0.5 * step;
            double sixth = step / 6.0;
            bool spins = _decay.IsPresent;
            bool positions = _windVaries;
            Vector3d p = state.Position, w = state.AngularVelocity;
            double vx = state.Velocity.X, vy = state.Velocity.Y, vz = state.Velocity.Z;

            // The slope that forms the next stage (velocity, acceleration, spin acceleration), and k2 (then k2 + k3).
            double vkx = vx, vky = vy, vkz = vz, akx = k1.Acceleration.X, aky = k1.Acceleration.Y, akz = k1.Acceleration.Z;
            Vector3d sk = k1.AngularAcceleration;
            double v23x = 0, v23y = 0, v23z = 0, a23x = 0, a23y = 0, a23z = 0;
            Vector3d s23 = default;
            Vector3d ps = p, ws = w;
            double vsx, vsy, vsz;
            double time = state.Time + step;
            SpinRates(w.X, w.Y, w.Z, out double spinRate, out double inverseSpinRate); // the whole step's, when the spin is constant

            for (int stage = 0; ; stage++)
            {
                if (stage < 3)
                {
                    // x + c k, FlightState.Advance's expression
                    double c = stage == 2 ? step : half;
                    vsx = vx + c * akx;
                    vsy = vy + c * aky;
                    vsz = vz + c * akz;
                    if (spins)
                    {
                        ws = Add(w, sk, c);
                    }

                    if (positions)
                    {
                        ps = new Vector3d(p.X + c * vkx, p.Y + c * vky, p.Z + c * vkz);
                    }
                }
                else
                {
                    // y + (k1 + 2 (k2 + k3) + k4) h/6, grouped as RungeKutta4 groups it (vk, ak, sk hold k4)
                    Vector3d k1v = k1.Velocity, k1a = k1.Acceleration;
                    ps = new Vector3d(
                        p.X + (k1v.X + v23x * 2.0 + vkx) * sixth,
                        p.Y + (k1v.Y + v23y * 2.0 + vky) * sixth,
                        p.Z + (k1v.Z + v23z * 2.0 + vkz) * sixth);
                    vsx = vx + (k1a.X + a23x * 2.0 + akx) * sixth;
                    vsy = vy + (k1a.Y + a23y * 2.0 + aky) * sixth;
                    vsz = vz + (k1a.Z + a23z * 2.0 + akz) * sixth;
                    ws = spins ? w + (k1.AngularAcceleration + 2.0 * s23 + sk) * sixth : w + k1.AngularAcceleration * sixth;
                }

                if (spins)
                {
                    SpinRates(ws.X, ws.Y, ws.Z, out spinRate, out inverseSpinRate);
                }

                Rates(ps, vsx, vsy, vsz, ws, spinRate, inverseSpinRate, out Vector3d a, out Vector3d s);
                if (stage == 3)
                {
                    var ve = new Vector3d(vsx, vsy, vsz);
                    next = new FlightState(ps, ve, ws, time);
                    end = new StateDerivative(ve, a, s);
                    return;
                }

                if (stage == 0)
                {
                    v23x = vsx;
                    v23y = vsy;
                    v23z = vsz;
                    a23x = a.X;
                    a23y = a.Y;
                    a23z = a.Z;
                    s23 = s;
                }
                else if (stage == 1)
                {
                    v23x += vsx;
                    v23y += vsy;
                    v23z += vsz;
                    a23x += a.X;
                    a23y += a.Y;
                    a23z += a.Z;
                    s23 += s;
                }

                vkx = vsx;
                vky = vsy;
                vkz = vsz;
                akx = a.X;
                aky = a.Y;
                akz = a.Z;
                sk = s;
            }
        }

        // One evaluation of an RK4 stage: the spin rates at the stage's spin where the spin changes, then the rates.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private void Stage(
            in Vector3d position, double vx, double vy, double vz, in Vector3d spin, ref double spinRate, ref double inverseSpinRate,
            out Vector3d acceleration, out Vector3d spinAcceleration)
        {
            if (_decay.IsPresent)
            {
                SpinRates(spin.X, spin.Y, spin.Z, out spinRate, out inverseSpinRate);
            }

            Rates(position, vx, vy, vz, spin, spinRate, inverseSpinRate, out acceleration, out spinAcceleration);
        }
    }
}
