// BallBatch, part: the vector lanes (StepVector), RK4 on Vector<double>.Count balls at once with System.Numerics vectors;
// a lane whose step may hold a landing is finished through the scalar path's Finish. The batch itself and the scalar lanes are in BallBatch.cs.
using System.Numerics;

using MagnusBall.Integration.Kernels;

namespace MagnusBall.Batch
{
    public sealed partial class BallBatch
    {
        // One RK4 step of the lanes [start, start + width): RungeKutta4's arithmetic lane by lane. Lanes that do not fly
        // (landed, diverged, padding) keep their values; lanes whose step may hold a landing are finished one by one
        // through the scalar path's Finish with the very numbers computed here, and lanes that overflowed take the
        // scalar path's whole step (StepScalar).
        private void StepVector(int start, double step)
        {
            var active = new Vector<long>(_active, start);
            if (Vector.EqualsAll(active, Vector<long>.Zero))
            {
                return;
            }

            ref readonly VectorLaws laws = ref _laws;
            var h = new Vector<double>(step);
            var half = new Vector<double>(0.5 * step);
            var sixth = new Vector<double>(step / 6.0);
            var two = new Vector<double>(2.0);

            Vector<double> px = new Vector<double>(_px, start), py = new Vector<double>(_py, start), pz = new Vector<double>(_pz, start);
            Vector<double> vx = new Vector<double>(_vx, start), vy = new Vector<double>(_vy, start), vz = new Vector<double>(_vz, start);
            Vector<double> wx = new Vector<double>(_wx, start), wy = new Vector<double>(_wy, start), wz = new Vector<double>(_wz, start);
            Vector<double> ax = new Vector<double>(_ax, start), ay = new Vector<double>(_ay, start), az = new Vector<double>(_az, start);
            Vector<double> sx = new Vector<double>(_sx, start), sy = new Vector<double>(_sy, start), sz = new Vector<double>(_sz, start);
            if (!Vector.LessThanOrEqualAll(wx * wx + wy * wy + wz * wz, new Vector<double>(double.MaxValue)))
            {
                // A spin rate past about 1.3e154 rad/s: the lanes' plain |w| (VectorLaws) would be infinite where the kernel's
                // scaled one is not, so these balls take the per-ball kernel step, whose numbers the vector lanes equal
                // everywhere else.
                StepScalarLanes(start, step);
                return;
            }

            bool spins = laws.Decay != Aerodynamics.LaneForm.Off;

            // k2, k3, k4 and the end rates from one evaluation site (the laws inlined once), RungeKutta4's grouping.
            Vector<double> v2x = default, v2y = default, v2z = default, v3x = default, v3y = default, v3z = default;
            Vector<double> a2x = default, a2y = default, a2z = default, a3x = default, a3y = default, a3z = default;
            Vector<double> s2x = default, s2y = default, s2z = default, s3x = default, s3y = default, s3z = default;
            Vector<double> vkx = vx, vky = vy, vkz = vz, akx = ax, aky = ay, akz = az, skx = sx, sky = sy, skz = sz;
            Vector<double> npx = px, npy = py, npz = pz, nvx, nvy, nvz, nwx = wx, nwy = wy, nwz = wz;
            Vector<double> nax, nay, naz, nsx, nsy, nsz;
            // Lanes where a decaying spin's stage spin has squares past double.MaxValue (the check above sees only the
            // start spin; with an exponential decay and a step several time constants long, the stage spins of RK4 grow):
            // the kernel's step for those balls, as for the start spin. Likewise lanes the laws mark as computed otherwise than
            // the kernel computes them (Stepanek's lift outside its folded form's range).
            Vector<long> perBall = Vector<long>.Zero;
            for (int stage = 0; ; stage++)
            {
                if (stage < 3)
                {
                    Vector<double> c = stage == 2 ? h : half;
                    nvx = vx + c * akx;
                    nvy = vy + c * aky;
                    nvz = vz + c * akz;
                    if (spins)
                    {
                        nwx = wx + c * skx;
                        nwy = wy + c * sky;
                        nwz = wz + c * skz;
                    }
                }
                else
                {
                    npx = px + (vx + two * (v2x + v3x) + vkx) * sixth;
                    npy = py + (vy + two * (v2y + v3y) + vky) * sixth;
                    npz = pz + (vz + two * (v2z + v3z) + vkz) * sixth;
                    nvx = vx + (ax + two * (a2x + a3x) + akx) * sixth;
                    nvy = vy + (ay + two * (a2y + a3y) + aky) * sixth;
                    nvz = vz + (az + two * (a2z + a3z) + akz) * sixth;
                    if (spins)
                    {
                        nwx = wx + (sx + two * (s2x + s3x) + skx) * sixth;
                        nwy = wy + (sy + two * (s2y + s3y) + sky) * sixth;
                        nwz = wz + (sz + two * (s2z + s3z) + skz) * sixth;
                    }
                    else
                    {
                        nwx = wx + sx * sixth;
                        nwy = wy + sy * sixth;
                        nwz = wz + sz * sixth;
                    }
                }

                if (spins)
                {
                    perBall |= Vector.GreaterThan(nwx * nwx + nwy * nwy + nwz * nwz, new Vector<double>(double.MaxValue));
                }

                laws.Rates(nvx, nvy, nvz, nwx, nwy, nwz, out nax, out nay, out naz, out nsx, out nsy, out nsz, out Vector<long> unfolded);
                perBall |= unfolded;
                if (stage == 3)
                {
                    break;
                }

                if (stage == 0)
                {
                    v2x = nvx;
                    v2y = nvy;
                    v2z = nvz;
                    a2x = nax;
                    a2y = nay;
                    a2z = naz;
                    s2x = nsx;
                    s2y = nsy;
                    s2z = nsz;
                }
                else if (stage == 1)
                {
                    v3x = nvx;
                    v3y = nvy;
                    v3z = nvz;
                    a3x = nax;
                    a3y = nay;
                    a3z = naz;
                    s3x = nsx;
                    s3y = nsy;
                    s3z = nsz;
                }

                vkx = nvx;
                vky = nvy;
                vkz = nvz;
                akx = nax;
                aky = nay;
                akz = naz;
                skx = nsx;
                sky = nsy;
                skz = nsz;
            }

            // Which lanes need the scalar finish: a landing is possible (the cubic's lower bound over the step is not
            // clearly above the plane: min(f0, f1) <= 4/27 (max(-m0, 0) + max(m1, 0)), with a margin), or a number is
            // not finite (x - x is NaN exactly then).
            Vector3d n = Ground.Normal;
            var nx = new Vector<double>(n.X);
            var ny = new Vector<double>(n.Y);
            var nz = new Vector<double>(n.Z);
            Vector3d o = Ground.Point;
            Vector<double> f0 = (px - new Vector<double>(o.X)) * nx + (py - new Vector<double>(o.Y)) * ny + (pz - new Vector<double>(o.Z)) * nz;
            Vector<double> f1 = (npx - new Vector<double>(o.X)) * nx + (npy - new Vector<double>(o.Y)) * ny + (npz - new Vector<double>(o.Z)) * nz;
            Vector<double> m0 = (vx * nx + vy * ny + vz * nz) * h;
            Vector<double> m1 = (nvx * nx + nvy * ny + nvz * nz) * h;
            Vector<double> reach = new Vector<double>(HermiteBound) * (Vector.Max(-m0, Vector<double>.Zero) + Vector.Max(m1, Vector<double>.Zero)) +
                new Vector<double>(1e-9) * (Vector.Abs(f0) + Vector.Abs(f1) + Vector.Abs(m0) + Vector.Abs(m1));
            // Not "min(f0, f1) <= reach": a NaN distance (Plane.SignedDistance's overflow, which the scalar path forms
            // without NaN) must go to the scalar finish too, and a NaN fails every comparison.
            Vector<long> near = ~(Vector.GreaterThan(f0, reach) & Vector.GreaterThan(f1, reach));
            Vector<double> check = (npx - npx) + (npy - npy) + (npz - npz) + (nvx - nvx) + (nvy - nvy) + (nvz - nvz) +
                (nwx - nwx) + (nwy - nwy) + (nwz - nwz) + (nax - nax) + (nay - nay) + (naz - naz) + (nsx - nsx) + (nsy - nsy) + (nsz - nsz);
            Vector<long> bad = ~Vector.Equals(check, Vector<double>.Zero) | perBall;
            Vector<long> special = (near | bad) & active;
            Vector<long> plain = active & ~special;

            var nt = new Vector<double>(_t, start) + h;
            Vector.ConditionalSelect(plain, npx, px).CopyTo(_px, start);
            Vector.ConditionalSelect(plain, npy, py).CopyTo(_py, start);
            Vector.ConditionalSelect(plain, npz, pz).CopyTo(_pz, start);
            Vector.ConditionalSelect(plain, nvx, vx).CopyTo(_vx, start);
            Vector.ConditionalSelect(plain, nvy, vy).CopyTo(_vy, start);
            Vector.ConditionalSelect(plain, nvz, vz).CopyTo(_vz, start);
            Vector.ConditionalSelect(plain, nwx, wx).CopyTo(_wx, start);
            Vector.ConditionalSelect(plain, nwy, wy).CopyTo(_wy, start);
            Vector.ConditionalSelect(plain, nwz, wz).CopyTo(_wz, start);
            Vector.ConditionalSelect(plain, nax, ax).CopyTo(_ax, start);
            Vector.ConditionalSelect(plain, nay, ay).CopyTo(_ay, start);
            Vector.ConditionalSelect(plain, naz, az).CopyTo(_az, start);
            Vector.ConditionalSelect(plain, nsx, sx).CopyTo(_sx, start);
            Vector.ConditionalSelect(plain, nsy, sy).CopyTo(_sy, start);
            Vector.ConditionalSelect(plain, nsz, sz).CopyTo(_sz, start);
            Vector.ConditionalSelect(plain, nt, new Vector<double>(_t, start)).CopyTo(_t, start);

            if (Vector.EqualsAll(special, Vector<long>.Zero))
            {
                for (int lane = 0; lane < _width; lane++)
                {
                    _startsFlight[start + lane] &= plain[lane] == 0;
                }

                return;
            }

            for (int lane = 0; lane < _width; lane++)
            {
                int i = start + lane;
                if (special[lane] == 0)
                {
                    _startsFlight[i] &= plain[lane] == 0;
                    continue;
                }

                if (bad[lane] != 0)
                {
                    // A number the lane formed is not finite, or a stage spin's squares overflowed: the kernel's own step
                    // decides. The lanes' plain |v| and |w| are infinite past about 1.34e154 (m/s, rad/s) where the
                    // kernel's scaled ones are not (there the single-ball step can be finite and taken); everywhere else
                    // the kernel forms the same non-finite step and refuses it. The arrays still hold the lane's start.
                    StepScalar(i, step);
                    continue;
                }

                var s0 = new FlightState(new Vector3d(px[lane], py[lane], pz[lane]), new Vector3d(vx[lane], vy[lane], vz[lane]),
                    new Vector3d(wx[lane], wy[lane], wz[lane]), _t[i]);
                var d0 = new StateDerivative(s0.Velocity, new Vector3d(ax[lane], ay[lane], az[lane]), new Vector3d(sx[lane], sy[lane], sz[lane]));
                var s1 = new FlightState(new Vector3d(npx[lane], npy[lane], npz[lane]), new Vector3d(nvx[lane], nvy[lane], nvz[lane]),
                    new Vector3d(nwx[lane], nwy[lane], nwz[lane]), _t[i] + step);
                var d1 = new StateDerivative(s1.Velocity, new Vector3d(nax[lane], nay[lane], naz[lane]), new Vector3d(nsx[lane], nsy[lane], nsz[lane]));
                Finish(i, s0, d0, s1, d1);
            }
        }
    }
}
