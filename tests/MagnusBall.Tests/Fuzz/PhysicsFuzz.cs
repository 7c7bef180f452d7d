using System;
using MagnusBall.Aerodynamics;

namespace MagnusBall.Fuzz
{
    /// <summary>
    /// Seeded hostile calls into the public physics API (issue 15): random finite states and parameters over the whole
    /// range of doubles through the Ball, Air, Atmosphere, law and FlightModel constructors, the laws, Spin and
    /// FlightModel.Derivative. A call must return no NaN (and finite values for moderate input) or throw an
    /// ArgumentException naming a parameter. Shared by the suite's test and the benchmark project's long run.
    /// </summary>
    public sealed class PhysicsFuzz
    {
        private readonly Random _random;

        /// <summary>Creates the generator; the same seed gives the same calls.</summary>
        public PhysicsFuzz(int seed) => _random = new Random(seed);

        /// <summary>Calls made, NaN results, infinite results for moderate input, ArgumentExceptions without a parameter name, other exceptions.</summary>
        public long Calls, NaNs, InfiniteForModerate, UnnamedArgumentErrors, UndocumentedExceptions, ArgumentErrors;

        /// <summary>The first failure seen, for the message.</summary>
        public string? FirstFailure;

        /// <summary>Runs <paramref name="count"/> calls.</summary>
        public void Run(long count)
        {
            for (long i = 0; i < count; i++)
            {
                Calls++;
                int kind = _random.Next(6);
                bool moderate = _random.Next(3) == 0;
                Func<string> what = () => "?";
                try
                {
                    switch (kind)
                    {
                        case 0:
                        case 1:
                        case 2:
                            what = Derivative(moderate, out bool nan, out bool inf);
                            Judge(nan, inf && moderate, what);
                            break;
                        case 3:
                            what = Laws(moderate, out nan, out inf);
                            Judge(nan, inf && moderate, what);
                            break;
                        case 4:
                        {
                            Vector3d v = Vector(moderate), d = Vector(moderate);
                            double rate = Number(moderate);
                            what = () => $"Spin.Toward({v}, {d}, {rate:R})";
                            Vector3d w = Spin.Toward(v, d, rate);
                            Judge(HasNaN(w), !w.IsFinite && moderate, what);
                            break;
                        }

                        default:
                        {
                            double t = Number(moderate), p = Number(moderate), h = _random.NextDouble() * (_random.Next(2) == 0 ? 1 : 3) - 1;
                            what = () => $"Air.FromWeather({t:R}, {p:R}, {h:R})";
                            Air air = _random.Next(2) == 0 ? Air.FromWeather(t, p, h) : Air.AtAltitude(t * 100, null, h);
                            Judge(double.IsNaN(air.Density) || double.IsNaN(air.DynamicViscosity), !double.IsFinite(air.Density), what);
                            break;
                        }
                    }
                }
                catch (ArgumentException e)
                {
                    ArgumentErrors++;
                    if (string.IsNullOrEmpty(e.ParamName))
                    {
                        UnnamedArgumentErrors++;
                        FirstFailure ??= $"{what()}: ArgumentException without a parameter name: {e.Message}";
                    }
                }
                catch (Exception e)
                {
                    UndocumentedExceptions++;
                    FirstFailure ??= $"{what()}: {e.GetType().Name}: {e.Message}";
                }
            }
        }

        private void Judge(bool nan, bool infiniteForModerate, Func<string> what)
        {
            if (nan)
            {
                NaNs++;
                FirstFailure ??= what() + ": NaN";
            }

            if (infiniteForModerate)
            {
                InfiniteForModerate++;
                FirstFailure ??= what() + ": infinite for moderate input";
            }
        }

        private Func<string> Derivative(bool moderate, out bool nan, out bool inf)
        {
            var ball = new Ball(Positive(moderate), Positive(moderate), 0.05 + 0.95 * _random.NextDouble());
            var air = new Air(Math.Abs(Number(moderate)), Vector(moderate), Positive(moderate));
            if (_random.Next(4) == 0)
            {
                air = air.WithLogarithmicWind(Vector(moderate), 10, 0.03, Vector(moderate));
            }

            var model = new FlightModel(ball, air, Vector(moderate), Drag(moderate), Lift(moderate), Decay(moderate));
            var state = new FlightState(Vector(moderate), Vector(moderate), Vector(moderate), Number(moderate));
            StateDerivative d = model.Derivative(state);
            nan = HasNaN(d.Velocity) || HasNaN(d.Acceleration) || HasNaN(d.AngularAcceleration) ||
                  double.IsNaN(model.MechanicalEnergy(state)) || double.IsNaN(model.RotationalEnergy(state));
            inf = !d.Acceleration.IsFinite || !d.AngularAcceleration.IsFinite;
            return () => $"{model}.Derivative({state})";
        }

        private Func<string> Laws(bool moderate, out bool nan, out bool inf)
        {
            // AeroConditions is not validated (it is built per evaluation): its documented ranges are kept here.
            double viscosity = Math.Abs(Number(moderate));
            var c = new AeroConditions(Math.Abs(Number(moderate)), Math.Abs(Number(moderate)), Math.Abs(Number(moderate)),
                Math.Abs(Number(moderate)), Math.Abs(Number(moderate)), viscosity > 0 ? viscosity : 1.8e-5);
            IDragModel? drag = Drag(moderate);
            ILiftModel? lift = Lift(moderate);
            ISpinDecayModel? decay = Decay(moderate);
            double cd = drag?.DragCoefficient(c) ?? 0, cl = lift?.LiftCoefficient(c) ?? 0;
            Vector3d dw = decay?.SpinAcceleration(Vector(moderate), c) ?? default;
            nan = double.IsNaN(c.SpinParameter) || double.IsNaN(c.TransverseSpinParameter) || double.IsNaN(c.ReynoldsNumber) ||
                  double.IsNaN(cd) || double.IsNaN(cl) || HasNaN(dw);
            inf = !double.IsFinite(cd) || !double.IsFinite(cl) || !dw.IsFinite;
            return () => $"laws {drag} {lift} {decay} at S={c.SpinParameter:R} Re={c.ReynoldsNumber:R}";
        }

        private IDragModel? Drag(bool moderate) => _random.Next(7) switch
        {
            0 => null,
            1 => new ConstantDrag(Math.Abs(Number(moderate))),
            2 => StepanekDrag.Instance,
            3 => new LinearSpinDrag(Math.Abs(Number(moderate)), Math.Abs(Number(moderate))),
            4 => GoffCarreSoccerDrag.Instance,
            5 => NathanBaseballDrag.Instance,
            _ => ConstantDrag.ThesisTennis,
        };

        private ILiftModel? Lift(bool moderate) => _random.Next(7) switch
        {
            0 => null,
            1 => new ConstantLift(Number(moderate)),
            2 => StepanekLift.Instance,
            3 => new LinearSpinLift(Number(moderate)),
            4 => PiecewiseLinearLift.SoccerGoffCarre,
            5 => NathanBaseballLift.Instance,
            _ => new PiecewiseLinearLift(new[] { 0.0, Positive(moderate) }, new[] { Number(moderate), Number(moderate) }),
        };

        private ISpinDecayModel? Decay(bool moderate) => _random.Next(3) switch
        {
            0 => null,
            1 => new ExponentialSpinDecay(Positive(moderate)),
            _ => new SpeedProportionalSpinDecay(Math.Abs(Number(moderate))),
        };

        // Moderate: |x| in [1e-3, 1e3] or 0; otherwise log-uniform over all finite doubles, with the edges and some
        // invalid values (negative, zero) so the constructors' checks run too.
        private double Number(bool moderate)
        {
            if (moderate)
            {
                return _random.Next(10) == 0 ? 0 : (_random.Next(2) == 0 ? 1 : -1) * Math.Pow(10, -3 + 6 * _random.NextDouble());
            }

            switch (_random.Next(10))
            {
                case 0:
                    return 0;
                case 1:
                    return _random.Next(2) == 0 ? double.MaxValue : -double.MaxValue;
                case 2:
                    return _random.Next(2) == 0 ? double.Epsilon : -double.Epsilon;
                default:
                    double m = Math.Pow(10, -323 + 631 * _random.NextDouble());
                    return double.IsFinite(m) ? (_random.Next(2) == 0 ? m : -m) : double.MaxValue;
            }
        }

        private double Positive(bool moderate)
        {
            double x = Math.Abs(Number(moderate));
            return _random.Next(50) == 0 ? -x : x; // now and then an invalid one
        }

        private Vector3d Vector(bool moderate) => new Vector3d(Number(moderate), Number(moderate), Number(moderate));

        private static bool HasNaN(in Vector3d v) => double.IsNaN(v.X) || double.IsNaN(v.Y) || double.IsNaN(v.Z);
    }
}
