#nullable enable
using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Contact;
using MagnusBall.Integration;

namespace MagnusBall.Samples.TennisScene
{
    /// <summary>
    /// The physical settings of the scene, the same ones the thesis's start screen offered (Agrawal 2023,
    /// section 3.3): ball mass, air density, Magnus and drag coefficients, plus the integrator and the fixed
    /// step. Immutable; builds the shared <see cref="FlightModel"/>.
    /// </summary>
    public sealed class SceneSettings
    {
        /// <summary>Creates settings; every default is the tennis ball of Cross (2011) under Stepanek's coefficients.</summary>
        /// <param name="massKg">Ball mass, kg.</param>
        /// <param name="radiusM">Ball radius, m.</param>
        /// <param name="airDensity">Air density, kg/m^3 (1.21: Cross 2011; the thesis's game used 1.29).</param>
        /// <param name="useStepanekCoefficients">
        /// True: Stepanek's spin-dependent C_D and C_L (validated against Cross's tennis angles); false: the
        /// constants below, as in the thesis.
        /// </param>
        /// <param name="dragCoefficient">Constant C_D when not using Stepanek's (thesis: 0.55).</param>
        /// <param name="magnusCoefficient">Constant C_M (lift) when not using Stepanek's (thesis: 0.175).</param>
        /// <param name="integrator">Integrator name: euler, semi-implicit-euler, heun, rk4 (see <see cref="Integrators.Names"/>) or stable-rk4.</param>
        /// <param name="fixedStep">Fixed step, s.</param>
        /// <param name="surface">
        /// The court: hard, clay or grass (the Cross bounce on <see cref="Surface"/>'s presets), or none (the
        /// flight ends at the first landing).
        /// </param>
        /// <exception cref="ArgumentException">A value is out of range, or the integrator or surface is unknown.</exception>
        public SceneSettings(
            double massKg = 0.057,
            double radiusM = 0.033,
            double airDensity = 1.21,
            bool useStepanekCoefficients = true,
            double dragCoefficient = 0.55,
            double magnusCoefficient = 0.175,
            string integrator = "rk4",
            double fixedStep = 1.0 / 240,
            string surface = "hard")
        {
            Ball = new Ball(massKg, radiusM, Ball.Tennis.InertiaFactor);
            Air = new Air(airDensity);
            UseStepanekCoefficients = useStepanekCoefficients;
            DragCoefficient = dragCoefficient;
            MagnusCoefficient = magnusCoefficient;
            // "stable-rk4": RK4 with the library's stability-safe substeps (worth it at a large fixed step, e.g.
            // FixedUpdate's 0.02 s, with light fast balls); otherwise one of Integrators.Names.
            Integrator = string.Equals(integrator, ((IIntegrator)StableIntegrator.RungeKutta4).Name, StringComparison.OrdinalIgnoreCase)
                ? StableIntegrator.RungeKutta4
                : Integrators.FromName(integrator);
            if (!(fixedStep > 0) || double.IsInfinity(fixedStep))
            {
                throw new ArgumentOutOfRangeException(nameof(fixedStep), fixedStep, $"fixedStep must be finite and > 0 s; got {fixedStep}.");
            }

            FixedStep = fixedStep;
            SurfaceName = surface ?? throw new ArgumentNullException(nameof(surface));
            Bounce = string.Equals(surface, "none", StringComparison.OrdinalIgnoreCase) ? null : new CrossBounce(Surface.FromName(surface));
            Model = new FlightModel(
                Ball, Air, Gravity.Along(TennisCourt.Up),
                useStepanekCoefficients ? (IDragModel)StepanekDrag.Instance : new ConstantDrag(dragCoefficient),
                useStepanekCoefficients ? (ILiftModel)StepanekLift.Instance : new ConstantLift(magnusCoefficient));
        }

        /// <summary>The ball.</summary>
        public Ball Ball { get; }

        /// <summary>The air.</summary>
        public Air Air { get; }

        /// <summary>True when Stepanek's coefficients are used.</summary>
        public bool UseStepanekCoefficients { get; }

        /// <summary>Constant C_D (used when not Stepanek).</summary>
        public double DragCoefficient { get; }

        /// <summary>Constant C_M (used when not Stepanek).</summary>
        public double MagnusCoefficient { get; }

        /// <summary>The integrator.</summary>
        public IIntegrator Integrator { get; }

        /// <summary>The fixed step, s.</summary>
        public double FixedStep { get; }

        /// <summary>The court surface's name (hard, clay, grass, or none).</summary>
        public string SurfaceName { get; }

        /// <summary>The bounce model (Cross's slide/grip bounce on the chosen surface), or null for none.</summary>
        public IBounceModel? Bounce { get; }

        /// <summary>The flight model: gravity along -y (Unity's and the court's down), drag and Magnus lift.</summary>
        public FlightModel Model { get; }

        /// <summary>A one-line description for logs and tables.</summary>
        public string Describe() =>
            string.Format(
                System.Globalization.CultureInfo.InvariantCulture,
                "ball {0} kg, r {1} m; air {2} kg/m^3; {3}; {4} at {5:G4} s; court: {6}",
                Ball.Mass, Ball.Radius, Air.Density,
                UseStepanekCoefficients ? "Stepanek C_D(S), C_L(S)" : $"C_D {DragCoefficient}, C_M {MagnusCoefficient}",
                Integrator.Name, FixedStep, Bounce == null ? "no bounce" : SurfaceName + " (Cross bounce)");
    }
}
