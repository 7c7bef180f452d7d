// FlightKernel, part: the Dormand-Prince 5(4) step on the kernel (DormandPrince54 and its stages, Dp54Stage), each stage's
// rates from FlightKernel.Rates.cs, the stage sums formed as the tableau's Combine forms them. The kernel's entry points
// are in FlightKernel.cs.
using System.Runtime.CompilerServices;
using MagnusBall.Integration;
using DP = MagnusBall.Integration.DormandPrince54;

namespace MagnusBall.Integration.Kernels
{
    internal sealed partial class FlightKernel<TDrag, TLift, TDecay>
    {
        internal override bool DormandPrince54(in FlightState state, in StateDerivative k1, double step, ref DormandPrince54Stages stages)
        {
            // DormandPrince54's arithmetic term by term (Dp54Stage forms each stage from k1 and the stages written so far).
            // One evaluation site (a loop over k2..k7), so the inlined laws appear once in the code; the stage positions are
            // formed only where the wind depends on the height, the stage spins only where the spin decays (otherwise every
            // stage spin is the start spin plus zero rates); the end state is formed in full. The rates go straight into the
            // caller's stages, no table of its own (a 432-byte table of k1..k6, zeroed on entry and copied out at the end,
            // cost 6-8 % of an adaptive step on .NET; docs/performance.md).
            double h = step;
            double check = 0; // the sum of every stage's rates: finite when each of them is (or spuriously not, on overflow)
            Vector3d w0 = state.AngularVelocity;
            SpinRates(w0.X, w0.Y, w0.Z, out double spinRate, out double inverseSpinRate); // the whole step's, when the spin is constant
            for (int stage = 1; ; stage++)
            {
                // stage 1..5: k2..k6; stage 6: the end, where k7 is evaluated
                Dp54Stage(k1, ref stages, stage, h, state, out Vector3d ps, out Vector3d vs, out Vector3d ws);
                bool end = stage == 6;
                if (_decay.IsPresent || end)
                {
                    SpinRates(ws.X, ws.Y, ws.Z, out spinRate, out inverseSpinRate);
                }

                Rates(ps, vs.X, vs.Y, vs.Z, ws, spinRate, inverseSpinRate, out Vector3d a, out Vector3d s);
                check += a.X + a.Y + a.Z + s.X + s.Y + s.Z;
                switch (stage)
                {
                    case 1:
                        stages.K2.Set(vs, a, s);
                        break;
                    case 2:
                        stages.K3.Set(vs, a, s);
                        break;
                    case 3:
                        stages.K4.Set(vs, a, s);
                        break;
                    case 4:
                        stages.K5.Set(vs, a, s);
                        break;
                    case 5:
                        stages.K6.Set(vs, a, s);
                        break;
                    default:
                        stages.End = new FlightState(ps, vs, ws, state.Time + h);
                        stages.K7 = new StateDerivative(vs, a, s);
                        return double.IsFinite(check);
                }
            }
        }

        // Stage `stage` of Dormand-Prince 5(4) (1..5: the states of k2..k6; 6: the fifth-order end): y + (h a_i1) k1 +
        // (h a_i2) k2 + ..., left to right as DormandPrince54's Combine sums it (stage 1 as FlightState.Advance(k1, a21 h));
        // the end leaves k2 out (b2 = 0), as there. k2..k6 are read from the stages written so far. Not inlined: one small
        // copy serves the loop above.
        [MethodImpl(MethodImplOptions.NoInlining)]
        private void Dp54Stage(in StateDerivative k1, ref DormandPrince54Stages k, int stage, double h, in FlightState y, out Vector3d ps, out Vector3d vs, out Vector3d ws)
        {
            bool spins = _decay.IsPresent, positions = _windVaries;
            Vector3d p = y.Position, v = y.Velocity, w = y.AngularVelocity;
            ps = p;
            ws = w;
            switch (stage)
            {
                case 1:
                {
                    double c = DP.A21 * h;
                    vs = Add(v, k1.Acceleration, c);
                    if (spins)
                    {
                        ws = Add(w, k1.AngularAcceleration, c);
                    }

                    if (positions)
                    {
                        ps = Add(p, k1.Velocity, c);
                    }

                    return;
                }

                case 2:
                {
                    double ha = h * DP.A31, hb = h * DP.A32;
                    vs = Add(Add(v, k1.Acceleration, ha), k.K2.Acceleration, hb);
                    if (spins)
                    {
                        ws = Add(Add(w, k1.AngularAcceleration, ha), k.K2.AngularAcceleration, hb);
                    }

                    if (positions)
                    {
                        ps = Add(Add(p, k1.Velocity, ha), k.K2.Velocity, hb);
                    }

                    return;
                }

                case 3:
                {
                    double ha = h * DP.A41, hb = h * DP.A42, hc = h * DP.A43;
                    vs = Add(Add(Add(v, k1.Acceleration, ha), k.K2.Acceleration, hb), k.K3.Acceleration, hc);
                    if (spins)
                    {
                        ws = Add(Add(Add(w, k1.AngularAcceleration, ha), k.K2.AngularAcceleration, hb), k.K3.AngularAcceleration, hc);
                    }

                    if (positions)
                    {
                        ps = Add(Add(Add(p, k1.Velocity, ha), k.K2.Velocity, hb), k.K3.Velocity, hc);
                    }

                    return;
                }

                case 4:
                {
                    double ha = h * DP.A51, hb = h * DP.A52, hc = h * DP.A53, hd = h * DP.A54;
                    vs = Add(Add(Add(Add(v, k1.Acceleration, ha), k.K2.Acceleration, hb), k.K3.Acceleration, hc), k.K4.Acceleration, hd);
                    if (spins)
                    {
                        ws = Add(Add(Add(Add(w, k1.AngularAcceleration, ha), k.K2.AngularAcceleration, hb), k.K3.AngularAcceleration, hc), k.K4.AngularAcceleration, hd);
                    }

                    if (positions)
                    {
                        ps = Add(Add(Add(Add(p, k1.Velocity, ha), k.K2.Velocity, hb), k.K3.Velocity, hc), k.K4.Velocity, hd);
                    }

                    return;
                }

                case 5:
                {
                    double ha = h * DP.A61, hb = h * DP.A62, hc = h * DP.A63, hd = h * DP.A64, he = h * DP.A65;
                    vs = Add(Add(Add(Add(Add(v, k1.Acceleration, ha), k.K2.Acceleration, hb), k.K3.Acceleration, hc), k.K4.Acceleration, hd), k.K5.Acceleration, he);
                    if (spins)
                    {
                        ws = Add(Add(Add(Add(Add(w, k1.AngularAcceleration, ha), k.K2.AngularAcceleration, hb), k.K3.AngularAcceleration, hc), k.K4.AngularAcceleration, hd), k.K5.AngularAcceleration, he);
                    }

                    if (positions)
                    {
                        ps = Add(Add(Add(Add(Add(p, k1.Velocity, ha), k.K2.Velocity, hb), k.K3.Velocity, hc), k.K4.Velocity, hd), k.K5.Velocity, he);
                    }

                    return;
                }

                default:
                {
                    double ha = h * DP.B1, hc = h * DP.B3, hd = h * DP.B4, he = h * DP.B5, hf = h * DP.B6;
                    vs = Add(Add(Add(Add(Add(v, k1.Acceleration, ha), k.K3.Acceleration, hc), k.K4.Acceleration, hd), k.K5.Acceleration, he), k.K6.Acceleration, hf);
                    ws = Add(Add(Add(Add(Add(w, k1.AngularAcceleration, ha), k.K3.AngularAcceleration, hc), k.K4.AngularAcceleration, hd), k.K5.AngularAcceleration, he), k.K6.AngularAcceleration, hf);
                    ps = Add(Add(Add(Add(Add(p, k1.Velocity, ha), k.K3.Velocity, hc), k.K4.Velocity, hd), k.K5.Velocity, he), k.K6.Velocity, hf);
                    return;
                }
            }
        }
    }
}
