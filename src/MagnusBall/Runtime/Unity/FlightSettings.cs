#nullable enable
using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Contact;
using MagnusBall.Integration;
using MagnusBall.Presets;

namespace MagnusBall.Components
{
    /// <summary>Which integrator steps the ball (an inspector drop-down).</summary>
    public enum IntegratorChoice
    {
        /// <summary>Classic RK4 (fourth order): the default.</summary>
        RungeKutta4 = 0,

        /// <summary>RK4 with stability-safe substeps (StableIntegrator): for long fixed steps with light, fast balls.</summary>
        StableRungeKutta4 = 1,

        /// <summary>Heun / RK2 (second order).</summary>
        Heun = 2,

        /// <summary>Semi-implicit Euler (first order; what PhysX does).</summary>
        SemiImplicitEuler = 3,

        /// <summary>Explicit Euler (first order).</summary>
        Euler = 4,
    }

    /// <summary>What the ball bounces on (an inspector drop-down).</summary>
    public enum SurfaceChoice
    {
        /// <summary>The preset's own bounce (tennis: a hard court); none if the preset has none.</summary>
        Preset = 0,

        /// <summary>No bounce: the flight ends where the ball first comes down.</summary>
        None = 1,

        /// <summary>Cross's slide/grip bounce on a hard court.</summary>
        Hard = 2,

        /// <summary>Cross's bounce on clay.</summary>
        Clay = 3,

        /// <summary>Cross's bounce on grass.</summary>
        Grass = 4,
    }

    /// <summary>
    /// The ball, its aerodynamics and the air, as the inspector shows them: a preset by name
    /// (<see cref="SportPresets.Names"/>: tennis, soccer, baseball, golf, table-tennis, ...), optionally with
    /// its ball or its drag and lift replaced by constants. Shared by the package's components.
    /// </summary>
    [Serializable]
    public sealed class FlightSettings
    {
        /// <summary>The preset's name (see <see cref="SportPresets.Names"/>).</summary>
        [UnityEngine.Tooltip("Preset: tennis, tennis-free-flight, soccer, baseball, golf, golf-bearman-harvey, golf-linear-2023, golf-smits-smith, table-tennis, basketball.")]
        public string preset = "tennis";

        /// <summary>Replace the preset's ball by <see cref="mass"/>, <see cref="radius"/> and <see cref="inertiaFactor"/>.</summary>
        [UnityEngine.Tooltip("Use the mass, radius and inertia factor below instead of the preset's ball.")]
        public bool customBall;

        /// <summary>Ball mass, kg (with <see cref="customBall"/>).</summary>
        [UnityEngine.Tooltip("kg")]
        public float mass = 0.057f;

        /// <summary>Ball radius, m (with <see cref="customBall"/>).</summary>
        [UnityEngine.Tooltip("m")]
        public float radius = 0.033f;

        /// <summary>Moment of inertia over m r^2 (with <see cref="customBall"/>): 0.4 solid, 2/3 thin shell, 0.55 tennis.</summary>
        [UnityEngine.Tooltip("I / (m r^2): 0.4 solid sphere, 0.667 thin shell, 0.55 tennis ball.")]
        public float inertiaFactor = 0.55f;

        /// <summary>Replace the preset's drag and lift laws by the constants <see cref="dragCoefficient"/> and <see cref="liftCoefficient"/>.</summary>
        [UnityEngine.Tooltip("Use the constant C_D and C_L below instead of the preset's laws.")]
        public bool constantCoefficients;

        /// <summary>Constant drag coefficient C_D (with <see cref="constantCoefficients"/>).</summary>
        [UnityEngine.Tooltip("C_D (the thesis's tennis ball: 0.55)")]
        public float dragCoefficient = 0.55f;

        /// <summary>Constant lift (Magnus) coefficient C_L (with <see cref="constantCoefficients"/>).</summary>
        [UnityEngine.Tooltip("C_L (the thesis's tennis ball: 0.175)")]
        public float liftCoefficient = 0.175f;

        /// <summary>Air density, kg/m^3 (sea level 1.225; Cross's tennis measurements 1.21).</summary>
        [UnityEngine.Tooltip("kg/m^3 (sea level: 1.225)")]
        public float airDensity = (float)Air.SeaLevelDensity;

        /// <summary>What the ball bounces on.</summary>
        [UnityEngine.Tooltip("The bounce: the preset's, none, or Cross's model on a hard, clay or grass court.")]
        public SurfaceChoice surface = SurfaceChoice.Preset;

        /// <summary>The preset these settings start from.</summary>
        /// <exception cref="ArgumentException"><see cref="preset"/> is not a known name (the message lists them).</exception>
        public SportPreset Preset()
        {
            SportPreset chosen = Field(nameof(preset), () => SportPresets.FromName(preset));
            if (customBall)
            {
                chosen = chosen.WithBall(new Ball(mass, radius, inertiaFactor));
            }

            if (constantCoefficients)
            {
                chosen = chosen.WithDrag(new ConstantDrag(dragCoefficient)).WithLift(new ConstantLift(liftCoefficient));
            }

            return chosen;
        }

        /// <summary>The flight model in Unity's world: these settings under <paramref name="gravity"/>.</summary>
        /// <param name="gravity">Gravity, m/s^2 (usually <see cref="Gravity.YUp"/>).</param>
        /// <exception cref="ArgumentException">A setting is out of range (the message names it).</exception>
        public FlightModel CreateModel(Vector3d gravity)
        {
            SportPreset chosen = Preset();
            Air air = Field(nameof(airDensity), () => new Air(airDensity));
            return chosen.CreateModel(air, gravity);
        }

        // An inspector field's value through a library constructor: its refusal named by the field, not the constructor's
        // parameter ("airDensity", not "density"). Configuration time only (the delegate is not per frame).
        internal static T Field<T>(string field, Func<T> make)
        {
            try
            {
                return make();
            }
            catch (ArgumentException e) when (e.ParamName != field)
            {
                throw new ArgumentException($"{field} (the inspector field): {e.Message}", field, e);
            }
        }

        /// <summary>The bounce model <see cref="surface"/> selects, or null for none.</summary>
        public IBounceModel? CreateBounce()
        {
            switch (surface)
            {
                case SurfaceChoice.None: return null;
                case SurfaceChoice.Hard: return CrossBounce.Hard;
                case SurfaceChoice.Clay: return CrossBounce.Clay;
                case SurfaceChoice.Grass: return new CrossBounce(Surface.Grass);
                default: return Preset().Bounce;
            }
        }

        /// <summary>The integrator for a choice.</summary>
        /// <param name="choice">The inspector's choice.</param>
        public static IIntegrator Integrator(IntegratorChoice choice)
        {
            switch (choice)
            {
                case IntegratorChoice.Euler: return ExplicitEuler.Instance;
                case IntegratorChoice.SemiImplicitEuler: return SemiImplicitEuler.Instance;
                case IntegratorChoice.Heun: return Heun.Instance;
                case IntegratorChoice.StableRungeKutta4: return StableIntegrator.RungeKutta4;
                default: return RungeKutta4.Instance;
            }
        }
    }
}
