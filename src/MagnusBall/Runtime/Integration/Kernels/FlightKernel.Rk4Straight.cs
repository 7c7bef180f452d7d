// FlightKernel, part: RK4's straight-line forms, taken under Mono and IL2CPP (PreferStraightLine, FlightKernel.cs): the
// thesis model's common case (Rk4Straight) and Stepanek's tennis laws folded in still air (Rk4StraightStepanek), each the
// same bits as the general shape. Rk4 (FlightKernel.Rk4.cs) picks them; the entry points are in FlightKernel.cs.
using System.Runtime.CompilerServices;
using MagnusBall.Aerodynamics;

namespace MagnusBall.Integration.Kernels
{
    internal sealed partial class FlightKernel<TDrag, TLift, TDecay>
    {
        // The laws and air Rk4Straight is written for (with laws that read nothing): drag and lift, no spin decay, still air.
        private bool StraightLineCase
        {
            [MethodImpl(MethodImplOptions.AggressiveInlining)] // Mono inlines only tiny methods without it
            get => _drag.IsPresent && _lift.IsPresent && !_decay.IsPresent && _stillAir;
        }

        // Rk4Unrolled's arithmetic, operation for operation, for constant drag and lift, a constant spin, still air and
        // no evaluation counter, as one basic block: the branches of every evaluation (the counter, the wind,
        // Vector3d.LengthOf's range test, the minimum speed, the lift's spin test) become one test at the end (a state
        // without lift is declined first). Mono's JIT keeps no double in a register from one basic block to the next, so
        // there every branch stored and reloaded the whole dependent chain (docs/performance.md). False, with end written
        // but not meaningful (it is the caller's next state, so it must not be a part of state), where a stage leaves the common case (a speed at or below
        // FlightModel.MinimumAerodynamicSpeed, a squared speed past double.MaxValue, a spin rate at or below
        // FlightModel.MinimumLiftSpinRate): Rk4Unrolled then takes the step its own way. Where it answers true, the result is Rk4Unrolled's bit for bit
        // (FlightKernelTests.StraightLineRk4_OnAdversarialStates_IsTheGeneralStep_BitForBit: the same steps on a model with
        // a counter attached, which takes the general code). The stages are written out, as in Rk4Unrolled: a shared stage
        // method would hand its results back through out parameters, which Mono keeps in memory.
        private bool Rk4Straight(in FlightState state, in StateDerivative k1, double step, out FlightState end, out Vector3d endAcceleration)
        {
            double half = 0.5 * step;
            double sixth = step / 6.0;
            Vector3d p = state.Position, w = state.AngularVelocity;
            double wx = w.X, wy = w.Y, wz = w.Z;
            double spinRate = Vector3d.LengthOf(wx, wy, wz);
            if (!(spinRate > FlightModel.MinimumLiftSpinRate))
            {
                // No lift (no spin, or at most FlightModel.MinimumLiftSpinRate): known before the chain starts, so the general
                // step is not paid on top of this one.
                end = default;
                endAcceleration = default;
                return false;
            }

            double inverseSpinRate = 1.0 / spinRate;
            // FoldedRates' -_factor C_D and _factor C_L (1/|w|), the same products (left to right).
            double dragFactor = -_factor * _drag.Coefficient(NoConditions);
            double liftFactor = _factor * _lift.Coefficient(NoConditions) * inverseSpinRate;
            double gx = _gravity.X, gy = _gravity.Y, gz = _gravity.Z;
            double vx = state.Velocity.X, vy = state.Velocity.Y, vz = state.Velocity.Z;
            Vector3d k1a = k1.Acceleration;
            bool common = true;

            // k2 at y + h/2 k1
            double v2x = vx + half * k1a.X, v2y = vy + half * k1a.Y, v2z = vz + half * k1a.Z;
            double squared = v2x * v2x + v2y * v2y + v2z * v2z;
            double speed = System.Math.Sqrt(squared);
            common &= squared <= double.MaxValue & speed > FlightModel.MinimumAerodynamicSpeed;
            double u2x = v2x * dragFactor + (wy * v2z - wz * v2y) * liftFactor;
            double u2y = v2y * dragFactor + (wz * v2x - wx * v2z) * liftFactor;
            double u2z = v2z * dragFactor + (wx * v2y - wy * v2x) * liftFactor;
            double a2x = gx + speed * u2x, a2y = gy + speed * u2y, a2z = gz + speed * u2z;

            // k3 at y + h/2 k2
            double v3x = vx + half * a2x, v3y = vy + half * a2y, v3z = vz + half * a2z;
            squared = v3x * v3x + v3y * v3y + v3z * v3z;
            speed = System.Math.Sqrt(squared);
            common &= squared <= double.MaxValue & speed > FlightModel.MinimumAerodynamicSpeed;
            double u3x = v3x * dragFactor + (wy * v3z - wz * v3y) * liftFactor;
            double u3y = v3y * dragFactor + (wz * v3x - wx * v3z) * liftFactor;
            double u3z = v3z * dragFactor + (wx * v3y - wy * v3x) * liftFactor;
            double a3x = gx + speed * u3x, a3y = gy + speed * u3y, a3z = gz + speed * u3z;

            // k4 at y + h k3
            double v4x = vx + step * a3x, v4y = vy + step * a3y, v4z = vz + step * a3z;
            squared = v4x * v4x + v4y * v4y + v4z * v4z;
            speed = System.Math.Sqrt(squared);
            common &= squared <= double.MaxValue & speed > FlightModel.MinimumAerodynamicSpeed;
            double u4x = v4x * dragFactor + (wy * v4z - wz * v4y) * liftFactor;
            double u4y = v4y * dragFactor + (wz * v4x - wx * v4z) * liftFactor;
            double u4z = v4z * dragFactor + (wx * v4y - wy * v4x) * liftFactor;
            double a4x = gx + speed * u4x, a4y = gy + speed * u4y, a4z = gz + speed * u4z;

            // y + (k1 + 2 (k2 + k3) + k4) h/6, and the end rates
            Vector3d k1v = k1.Velocity;
            Vector3d pe = EndPosition(p, k1v, v2x, v2y, v2z, v3x, v3y, v3z, v4x, v4y, v4z, sixth);
            double vex = vx + (k1a.X + (a2x + a3x) * 2.0 + a4x) * sixth;
            double vey = vy + (k1a.Y + (a2y + a3y) * 2.0 + a4y) * sixth;
            double vez = vz + (k1a.Z + (a2z + a3z) * 2.0 + a4z) * sixth;
            // The end rates at the end spin w + k1's spin rate h/6, as Rk4Unrolled evaluates them (with the start's |w|):
            // not w itself, which differs from it in the sign of a zero component (-0 + 0 is +0) and for a k1 whose spin
            // rate is not zero.
            Vector3d we = w + k1.AngularAcceleration * sixth;
            double ex = we.X, ey = we.Y, ez = we.Z;
            squared = vex * vex + vey * vey + vez * vez;
            speed = System.Math.Sqrt(squared);
            common &= squared <= double.MaxValue & speed > FlightModel.MinimumAerodynamicSpeed;
            endAcceleration = new Vector3d(
                gx + speed * (vex * dragFactor + (ey * vez - ez * vey) * liftFactor),
                gy + speed * (vey * dragFactor + (ez * vex - ex * vez) * liftFactor),
                gz + speed * (vez * dragFactor + (ex * vey - ey * vex) * liftFactor));
            end = new FlightState(pe, new Vector3d(vex, vey, vez), we, state.Time + step);
            return common;
        }

        // The laws and air Rk4StraightStepanek is written for: Stepanek's drag and lift, both folded (TryFoldedRates), any
        // spin decay, still air.
        private bool StepanekStraightCase
        {
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            get => typeof(TDrag) == typeof(StepanekDragLaw) && FoldsStepanekLift && _foldsLift && _stillAir;
        }

        // Rk4Loop's arithmetic, operation for operation, for Stepanek's drag and lift folded in still air with no evaluation
        // counter (the tennis model and its presets), as one basic block under Mono, as Rk4Straight is for the thesis model:
        // the branches of every evaluation (the fold's ranges, the table's row) become flags tested once at the end, and a
        // stage spin's LengthOf loses its branch (see StraightLength). False, with next written but not meaningful, where a
        // stage leaves that case (a spin rate, squared speed or squared |w x v| outside the fold's range, z outside the
        // table); the caller then takes Rk4Loop, which gives the general formula there. A start spin outside the fold's
        // range is declined before the chain starts.
        // Like Rk4Straight it hands back the end rates as two vectors, and the caller forms the end derivative only where it
        // answers: the caller's end derivative may be its k1 (IIntegrator.Step's callers pass one variable for both), which
        // a declined step must leave as it was for the general step.
        private bool Rk4StraightStepanek(
            in FlightState state, in StateDerivative k1, double step, out FlightState next, out Vector3d endAcceleration,
            out Vector3d endSpinAcceleration)
        {
            bool spins = _decay.IsPresent;
            Vector3d p = state.Position, w = state.AngularVelocity;
            double startRate = Vector3d.LengthOf(w.X, w.Y, w.Z); // SpinRates' |w| (the lift is present)
            if (!(startRate >= FoldMinimum && startRate <= FoldMaximum))
            {
                next = default;
                endAcceleration = default;
                endSpinAcceleration = default;
                return false;
            }

            double half = 0.5 * step;
            double sixth = step / 6.0;

            double vx = state.Velocity.X, vy = state.Velocity.Y, vz = state.Velocity.Z;
            Vector3d k1a = k1.Acceleration, k1s = k1.AngularAcceleration;
            bool common = true;

            // k2 at y + h/2 k1
            double v2x = vx + half * k1a.X, v2y = vy + half * k1a.Y, v2z = vz + half * k1a.Z;
            Vector3d w2 = spins ? Add(w, k1s, half) : w;
            double rate2 = spins ? StraightLength(w2) : startRate;
            StraightStepanekRates(v2x, v2y, v2z, w2, rate2, ref common, out double a2x, out double a2y, out double a2z, out Vector3d s2);

            // k3 at y + h/2 k2
            double v3x = vx + half * a2x, v3y = vy + half * a2y, v3z = vz + half * a2z;
            Vector3d w3 = spins ? Add(w, s2, half) : w;
            double rate3 = spins ? StraightLength(w3) : startRate;
            StraightStepanekRates(v3x, v3y, v3z, w3, rate3, ref common, out double a3x, out double a3y, out double a3z, out Vector3d s3);

            // k4 at y + h k3
            double v4x = vx + step * a3x, v4y = vy + step * a3y, v4z = vz + step * a3z;
            Vector3d w4 = spins ? Add(w, s3, step) : w;
            double rate4 = spins ? StraightLength(w4) : startRate;
            StraightStepanekRates(v4x, v4y, v4z, w4, rate4, ref common, out double a4x, out double a4y, out double a4z, out Vector3d s4);

            // y + (k1 + 2 (k2 + k3) + k4) h/6, grouped as Rk4Loop groups it, and the end rates
            Vector3d k1v = k1.Velocity;
            Vector3d pe = EndPosition(p, k1v, v2x, v2y, v2z, v3x, v3y, v3z, v4x, v4y, v4z, sixth);
            double vex = vx + (k1a.X + (a2x + a3x) * 2.0 + a4x) * sixth;
            double vey = vy + (k1a.Y + (a2y + a3y) * 2.0 + a4y) * sixth;
            double vez = vz + (k1a.Z + (a2z + a3z) * 2.0 + a4z) * sixth;
            Vector3d we = spins ? w + (k1s + 2.0 * (s2 + s3) + s4) * sixth : w + k1s * sixth;
            double rateEnd = spins ? StraightLength(we) : startRate;
            StraightStepanekRates(vex, vey, vez, we, rateEnd, ref common, out double aex, out double aey, out double aez, out endSpinAcceleration);
            next = new FlightState(pe, new Vector3d(vex, vey, vez), we, state.Time + step);
            endAcceleration = new Vector3d(aex, aey, aez);
            return common;
        }

        // Vector3d.LengthOf's common path, without its branch. Where LengthOf would take its scaled path instead (a square
        // that is 0, subnormal, past double.MaxValue or NaN), this rate is below 1.5e-154, infinite or NaN, and the fold's
        // spin-rate range, which StraightStepanekRates tests on every stage's rate, declines the step: no flag of its own.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double StraightLength(in Vector3d w) => System.Math.Sqrt(w.X * w.X + w.Y * w.Y + w.Z * w.Z);

        // TryFoldedRates for Stepanek's drag and lift in still air, operation for operation, without a branch: common cleared
        // where TryFoldedRates would decline or the table would (the results are then of no meaning).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private void StraightStepanekRates(
            double rx, double ry, double rz, in Vector3d spin, double spinRate, ref bool common,
            out double ax, out double ay, out double az, out Vector3d spinAcceleration)
        {
            double wx = spin.X, wy = spin.Y, wz = spin.Z;
            double qx = wy * rz - wz * ry, qy = wz * rx - wx * rz, qz = wx * ry - wy * rx; // w x v_rel
            double squared = rx * rx + ry * ry + rz * rz;
            double transverseSquared = qx * qx + qy * qy + qz * qz;
            common &= spinRate >= FoldMinimum & spinRate <= FoldMaximum & squared >= FoldMinimumSquare & squared <= FoldMaximumSquare &
                (transverseSquared == 0 | (transverseSquared >= FoldMinimumSquare & transverseSquared <= FoldMaximumSquare));
            double speed = System.Math.Sqrt(squared);
            double inverseSpinRate = 1.0 / spinRate;
            double liftScale = StepanekLiftFold(squared, transverseSquared, _radius, _factor * inverseSpinRate * speed);
            double z = squared * (_kappaOverRadiusSquared * (inverseSpinRate * inverseSpinRate));
            double spinPart = StepanekDrag.TableWithoutBranch(z, out bool inTable);
            common &= inTable;
            double scale = -_factor * speed;
            double ex = rx * scale, ey = ry * scale, ez = rz * scale;
            ax = (_gravity.X + ex * 0.508 + spinPart * ex) + qx * liftScale;
            ay = (_gravity.Y + ey * 0.508 + spinPart * ey) + qy * liftScale;
            az = (_gravity.Z + ez * 0.508 + spinPart * ez) + qz * liftScale;
            // (A law of the spin and the speed alone, as both built-in decays are, is given the speed instead of the conditions.)
            spinAcceleration = _decay.SpeedOnly ? _decay.SpinAccelerationAtSpeed(spin, speed)
                : _decay.IsPresent ? _decay.SpinAcceleration(spin, FoldedConditions(speed, spinRate)) : default;
        }
    }
}
