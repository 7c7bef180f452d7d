using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;

namespace MagnusBall.Benchmarks
{
    /// <summary>A ball with its aerodynamics, defined here so the benchmarks do not depend on presets.</summary>
    internal sealed class BallCase
    {
        public BallCase(string name, Ball ball, IDragModel drag, ILiftModel lift, double spinDecayTime)
        {
            Name = name;
            Ball = ball;
            Drag = drag;
            Lift = lift;
            SpinDecayTime = spinDecayTime;
        }

        public string Name { get; }

        public Ball Ball { get; }

        public IDragModel Drag { get; }

        public ILiftModel Lift { get; }

        public double SpinDecayTime { get; }

        public FlightModel Model(Vector3d gravity) =>
            new FlightModel(Ball, Air.SeaLevel, gravity, Drag, Lift, new ExponentialSpinDecay(SpinDecayTime));

        /// <summary>k C_D at no spin, 1/m: drag deceleration is k C_D s^2.</summary>
        public double DragRate(FlightModel model) =>
            model.AerodynamicFactor * Drag.DragCoefficient(new AeroConditions(30, 0, 0, Ball.Radius, model.Air.Density, model.Air.DynamicViscosity));
    }

    /// <summary>The balls, models and shots the reports use.</summary>
    internal static class Scenarios
    {
        public static readonly Vector3d Up = Vector3d.UnitZ;

        public static readonly Vector3d G = Gravity.ZUp;

        /// <summary>
        /// Six balls from the lightest-for-its-size to the densest. Masses and radii: ITTF (table tennis 2.7 g, 20 mm),
        /// ITF (tennis 57 g, 33 mm), FIFA size 5 (430 g, 110 mm), USGA golf (45.9 g, 21.3 mm), MLB baseball (145 g,
        /// 36.4 mm); the beach ball (120 g, 250 mm) is a typical 50 cm inflatable. Drag coefficients are the usual
        /// sub-critical values (table tennis 0.5, soccer 0.25, golf 0.25, baseball 0.35, beach ball 0.47; tennis
        /// Stepanek 1988); lift for all is Stepanek's saturating law, which keeps C_L below 0.5 at any spin.
        /// Spin-decay times: tennis 20 s, golf 25 s (TrackMan ~4 %/s), baseball 5 s (Nathan 2008); the others are
        /// round guesses (table tennis 2 s, soccer 10 s, beach ball 2 s), used only for robustness.
        /// </summary>
        public static readonly BallCase[] Balls =
        {
            new BallCase("table tennis", new Ball(0.0027, 0.020, Ball.ThinShellInertiaFactor), new ConstantDrag(0.5), StepanekLift.Instance, 2),
            new BallCase("tennis", Ball.Tennis, StepanekDrag.Instance, StepanekLift.Instance, 20),
            new BallCase("soccer", new Ball(0.43, 0.11, Ball.ThinShellInertiaFactor), new ConstantDrag(0.25), StepanekLift.Instance, 10),
            new BallCase("golf", new Ball(0.0459, 0.02135, 0.4), new ConstantDrag(0.25), StepanekLift.Instance, 25),
            new BallCase("baseball", new Ball(0.145, 0.0364, 0.4), new ConstantDrag(0.35), StepanekLift.Instance, 5),
            new BallCase("beach ball", new Ball(0.12, 0.25, Ball.ThinShellInertiaFactor), new ConstantDrag(0.47), StepanekLift.Instance, 2),
        };

        public static IIntegrator[] FixedStepIntegrators => new IIntegrator[]
        {
            ExplicitEuler.Instance, SemiImplicitEuler.Instance, Heun.Instance, RungeKutta4.Instance, DormandPrince54.Instance,
        };

        /// <summary>The full tennis model: Stepanek drag and lift, exponential spin decay (tau 20 s), rho 1.21.</summary>
        public static FlightModel FullTennis() =>
            new FlightModel(Ball.Tennis, new Air(1.21), G, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(FullTennisSpinDecayTime));

        /// <summary>The full tennis model's spin decay time constant, s.</summary>
        public const double FullTennisSpinDecayTime = 20;

        /// <summary>Drag only (Stepanek drag, no lift, constant spin).</summary>
        public static FlightModel DragOnlyTennis() => new FlightModel(Ball.Tennis, new Air(1.21), G, StepanekDrag.Instance);

        /// <summary>Gravity only.</summary>
        public static FlightModel VacuumTennis() => FlightModel.Vacuum(Ball.Tennis, G);

        /// <summary>The thesis's model: constant C_D 0.55 and C_M 0.175, constant spin, rho 1.21.</summary>
        public static FlightModel ThesisTennis() => FlightModel.Thesis(Ball.Tennis, new Air(1.21), G);

        /// <summary>A launch from height h at speed s and elevation e (deg) along +x, spin given by effect.</summary>
        public static FlightState Launch(double height, double speed, double elevationDegrees, double topspinRate, double sideSpinRate = 0)
        {
            double e = elevationDegrees * Math.PI / 180;
            var velocity = new Vector3d(speed * Math.Cos(e), 0, speed * Math.Sin(e));
            Vector3d spin = default;
            if (topspinRate != 0)
            {
                spin += topspinRate > 0 ? Spin.Topspin(velocity, Up, topspinRate) : Spin.Backspin(velocity, Up, -topspinRate);
            }

            if (sideSpinRate != 0)
            {
                spin += Spin.Toward(velocity, sideSpinRate > 0 ? Vector3d.UnitY : -Vector3d.UnitY, Math.Abs(sideSpinRate));
            }

            return new FlightState(new Vector3d(0, 0, height), velocity, spin);
        }

        /// <summary>The 40 m/s tennis topspin drive all the headline numbers use.</summary>
        public static FlightState TennisDrive() => Launch(1.0, 40, 6, Spin.FromRpm(2500));
    }

    /// <summary>One named shot for the work-precision report.</summary>
    internal sealed class Shot
    {
        public Shot(string name, FlightModel model, FlightState launch)
        {
            Name = name;
            Model = model;
            Launch = launch;
        }

        public string Name { get; }

        public FlightModel Model { get; }

        public FlightState Launch { get; }

        /// <summary>
        /// Five shots. Tennis (Stepanek, rho 1.21): a 40 m/s topspin drive at 6 deg with 2500 rpm; a 55 m/s flat serve
        /// from 2.8 m at -4 deg with 1500 rpm of sidespin. Soccer: a 25 m/s free kick at 16 deg with 62 rad/s of sidespin
        /// (Javorova &amp; Ivanov 2018's spin). Golf: a driver, 76.4 m/s (171 mph) at 10.4 deg with 2545 rpm of backspin
        /// (TrackMan tour averages). Table tennis: a 20 m/s topspin loop from 0.3 m at 20 deg with 100 rev/s.
        /// </summary>
        public static Shot[] All()
        {
            BallCase soccer = Scenarios.Balls[2], golf = Scenarios.Balls[3], tableTennis = Scenarios.Balls[0];
            return new[]
            {
                new Shot("tennis topspin drive", Scenarios.FullTennis(), Scenarios.TennisDrive()),
                new Shot("tennis serve", Scenarios.FullTennis(), Scenarios.Launch(2.8, 55, -4, 0, Spin.FromRpm(1500))),
                new Shot("soccer free kick", soccer.Model(Scenarios.G), Scenarios.Launch(0.11, 25, 16, 0, 62)),
                new Shot("golf drive", golf.Model(Scenarios.G), Scenarios.Launch(0.02, 76.4, 10.4, -Spin.FromRpm(2545))),
                new Shot("table-tennis loop", tableTennis.Model(Scenarios.G), Scenarios.Launch(0.3, 20, 20, Spin.FromRevolutionsPerSecond(100))),
            };
        }
    }
}
