using System;
using System.Runtime.CompilerServices;

namespace MagnusBall.Aerodynamics
{
    /// <summary>
    /// The inputs of <see cref="AeroConditions"/> a coefficient law reads, beyond the speed, radius and density that
    /// are always there: the flight kernel computes only the ones some law of the model reads.
    /// </summary>
    [Flags]
    internal enum AeroInputs
    {
        None = 0,

        /// <summary>|w| (<see cref="AeroConditions.SpinRate"/>, <see cref="AeroConditions.SpinRpm"/>).</summary>
        SpinRate = 1,

        /// <summary>S = r|w|/s (implies the spin rate).</summary>
        SpinParameter = 2 | SpinRate,

        /// <summary>|w x v_hat| (<see cref="AeroConditions.TransverseSpinRate"/>).</summary>
        TransverseSpinRate = 4,

        /// <summary>S_perp = r|w x v_hat|/s (implies the transverse spin rate).</summary>
        TransverseSpinParameter = 8 | TransverseSpinRate,

        /// <summary>The Reynolds number.</summary>
        ReynoldsNumber = 16,

        /// <summary>Everything (a law the kernel does not know, called through its public interface).</summary>
        All = SpinParameter | TransverseSpinParameter | ReynoldsNumber,
    }

    /// <summary>
    /// A drag law plugged into the flight kernel as a struct type parameter, so the JIT specialises and inlines it
    /// (the BepuPhysics2 pattern). <see cref="IsPresent"/> and <see cref="Reads"/> return constants, so the checks on
    /// them fold away. A law without such a struct runs through <see cref="InterfaceDrag"/>.
    /// </summary>
    internal interface IDragLaw
    {
        /// <summary>False only for <see cref="NoDrag"/>.</summary>
        bool IsPresent { get; }

        /// <summary>What the law reads.</summary>
        AeroInputs Reads { get; }

        /// <summary>C_D; must equal the public law's <see cref="IDragModel.DragCoefficient"/> bit for bit.</summary>
        double Coefficient(in AeroConditions conditions);
    }

    /// <summary>A lift law as a struct type parameter (see <see cref="IDragLaw"/>).</summary>
    internal interface ILiftLaw
    {
        /// <summary>False only for <see cref="NoLift"/>.</summary>
        bool IsPresent { get; }

        /// <summary>What the law reads.</summary>
        AeroInputs Reads { get; }

        /// <summary>C_L; must equal the public law's <see cref="ILiftModel.LiftCoefficient"/> bit for bit.</summary>
        double Coefficient(in AeroConditions conditions);
    }

    /// <summary>A spin-decay law as a struct type parameter (see <see cref="IDragLaw"/>).</summary>
    internal interface ISpinDecayLaw
    {
        /// <summary>False only for <see cref="NoSpinDecay"/>.</summary>
        bool IsPresent { get; }

        /// <summary>What the law reads.</summary>
        AeroInputs Reads { get; }

        /// <summary>dw/dt; must equal the public law's <see cref="ISpinDecayModel.SpinAcceleration"/> bit for bit.</summary>
        Vector3d SpinAcceleration(in Vector3d angularVelocity, in AeroConditions conditions);

        /// <summary>
        /// True when dw/dt depends on the spin and the air speed alone (the exponential and the speed-proportional decay):
        /// <see cref="SpinAccelerationAtSpeed"/> then gives <see cref="SpinAcceleration"/>'s bits without the conditions (Mono
        /// builds a 64-byte struct in memory for them; RK4's straight-line form for the tennis laws does without).
        /// </summary>
        bool SpeedOnly { get; }

        /// <summary>dw/dt at the air speed <paramref name="speed"/> where <see cref="SpeedOnly"/> (the conditions' Speed); zero otherwise.</summary>
        Vector3d SpinAccelerationAtSpeed(in Vector3d angularVelocity, double speed);
    }

    internal readonly struct NoDrag : IDragLaw
    {
        public bool IsPresent => false;

        public AeroInputs Reads => AeroInputs.None;

        public double Coefficient(in AeroConditions conditions) => 0;
    }

    internal readonly struct NoLift : ILiftLaw
    {
        public bool IsPresent => false;

        public AeroInputs Reads => AeroInputs.None;

        public double Coefficient(in AeroConditions conditions) => 0;
    }

    internal readonly struct NoSpinDecay : ISpinDecayLaw
    {
        public bool IsPresent => false;

        public AeroInputs Reads => AeroInputs.None;

        public Vector3d SpinAcceleration(in Vector3d angularVelocity, in AeroConditions conditions) => default;

        public bool SpeedOnly => false;

        public Vector3d SpinAccelerationAtSpeed(in Vector3d angularVelocity, double speed) => default;
    }

    /// <summary>Any <see cref="IDragModel"/> (a user's own law), called through the interface with every input computed.</summary>
    internal readonly struct InterfaceDrag : IDragLaw
    {
        private readonly IDragModel _law;

        public InterfaceDrag(IDragModel law) => _law = law;

        public bool IsPresent => true;

        public AeroInputs Reads => AeroInputs.All;

        public double Coefficient(in AeroConditions conditions) => _law.DragCoefficient(conditions);
    }

    /// <summary>Any <see cref="ILiftModel"/>, called through the interface with every input computed.</summary>
    internal readonly struct InterfaceLift : ILiftLaw
    {
        private readonly ILiftModel _law;

        public InterfaceLift(ILiftModel law) => _law = law;

        public bool IsPresent => true;

        public AeroInputs Reads => AeroInputs.All;

        public double Coefficient(in AeroConditions conditions) => _law.LiftCoefficient(conditions);
    }

    /// <summary>Any <see cref="ISpinDecayModel"/>, called through the interface with every input computed.</summary>
    internal readonly struct InterfaceSpinDecay : ISpinDecayLaw
    {
        private readonly ISpinDecayModel _law;

        public InterfaceSpinDecay(ISpinDecayModel law) => _law = law;

        public bool IsPresent => true;

        public AeroInputs Reads => AeroInputs.All;

        public Vector3d SpinAcceleration(in Vector3d angularVelocity, in AeroConditions conditions) =>
            _law.SpinAcceleration(angularVelocity, conditions);

        public bool SpeedOnly => false;

        public Vector3d SpinAccelerationAtSpeed(in Vector3d angularVelocity, double speed) => default;
    }

    internal readonly struct ConstantDragLaw : IDragLaw
    {
        private readonly double _value;

        public ConstantDragLaw(double value) => _value = value;

        public bool IsPresent => true;

        public AeroInputs Reads => AeroInputs.None;

        public double Coefficient(in AeroConditions conditions) => _value;
    }

    internal readonly struct StepanekDragLaw : IDragLaw
    {
        public bool IsPresent => true;

        public AeroInputs Reads => AeroInputs.SpinParameter;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public double Coefficient(in AeroConditions conditions) => StepanekDrag.FromConditions(conditions);
    }

    internal readonly struct LinearSpinDragLaw : IDragLaw
    {
        private readonly double _intercept, _slope;

        public LinearSpinDragLaw(LinearSpinDrag law)
        {
            _intercept = law.Intercept;
            _slope = law.Slope;
        }

        public bool IsPresent => true;

        public AeroInputs Reads => AeroInputs.SpinParameter;

        public double Coefficient(in AeroConditions conditions) => _intercept + _slope * conditions.SpinParameter;
    }

    internal readonly struct NathanBaseballDragLaw : IDragLaw
    {
        public bool IsPresent => true;

        public AeroInputs Reads => AeroInputs.SpinRate;

        public double Coefficient(in AeroConditions conditions) => NathanBaseballDrag.Evaluate(conditions.SpinRpm);
    }

    internal readonly struct GoffCarreSoccerDragLaw : IDragLaw
    {
        public bool IsPresent => true;

        public AeroInputs Reads => AeroInputs.SpinParameter;

        public double Coefficient(in AeroConditions conditions) => GoffCarreSoccerDrag.Evaluate(conditions.Speed, conditions.SpinParameter);
    }

    internal readonly struct ContiTableTennisDragLaw : IDragLaw
    {
        public bool IsPresent => true;

        public AeroInputs Reads => AeroInputs.SpinParameter;

        public double Coefficient(in AeroConditions conditions) => ContiTableTennisDrag.Evaluate(conditions.Speed, conditions.SpinParameter);
    }

    internal readonly struct ContiTableTennisLiftLaw : ILiftLaw
    {
        public bool IsPresent => true;

        public AeroInputs Reads => AeroInputs.SpinParameter;

        public double Coefficient(in AeroConditions conditions) =>
            ContiTableTennisLift.Evaluate(conditions.Speed, conditions.SpinRate, conditions.SpinParameter);
    }

    internal readonly struct PiecewiseLinearLiftLaw : ILiftLaw
    {
        private readonly PiecewiseLinearLift _table;

        public PiecewiseLinearLiftLaw(PiecewiseLinearLift table) => _table = table;

        public bool IsPresent => true;

        public AeroInputs Reads => AeroInputs.TransverseSpinParameter;

        public double Coefficient(in AeroConditions conditions) => _table.Evaluate(conditions.TransverseSpinParameter);
    }

    internal readonly struct ConstantLiftLaw : ILiftLaw
    {
        private readonly double _value;

        public ConstantLiftLaw(double value) => _value = value;

        public bool IsPresent => true;

        public AeroInputs Reads => AeroInputs.None;

        public double Coefficient(in AeroConditions conditions) => _value;
    }

    internal readonly struct LinearSpinLiftLaw : ILiftLaw
    {
        private readonly double _slope;

        public LinearSpinLiftLaw(double slope) => _slope = slope;

        public bool IsPresent => true;

        public AeroInputs Reads => AeroInputs.TransverseSpinParameter;

        public double Coefficient(in AeroConditions conditions) => _slope * conditions.TransverseSpinParameter;
    }

    internal readonly struct StepanekLiftLaw : ILiftLaw
    {
        public bool IsPresent => true;

        public AeroInputs Reads => AeroInputs.TransverseSpinParameter;

        public double Coefficient(in AeroConditions conditions) => StepanekLift.Evaluate(conditions.TransverseSpinParameter);
    }

    internal readonly struct NathanBaseballLiftLaw : ILiftLaw
    {
        public bool IsPresent => true;

        public AeroInputs Reads => AeroInputs.TransverseSpinParameter;

        public double Coefficient(in AeroConditions conditions) => NathanBaseballLift.Evaluate(conditions.TransverseSpinParameter);
    }

    internal readonly struct ExponentialSpinDecayLaw : ISpinDecayLaw
    {
        private readonly double _factor; // -1.0 / tau, the double ExponentialSpinDecay forms per call (the same bits)

        public ExponentialSpinDecayLaw(double timeConstant) => _factor = -1.0 / timeConstant;

        public bool IsPresent => true;

        public AeroInputs Reads => AeroInputs.None;

        // The same expression as ExponentialSpinDecay, its -1.0 / tau formed once (no division per evaluation or step).
        public Vector3d SpinAcceleration(in Vector3d angularVelocity, in AeroConditions conditions) =>
            angularVelocity * _factor;

        public bool SpeedOnly => true;

        public Vector3d SpinAccelerationAtSpeed(in Vector3d angularVelocity, double speed) => angularVelocity * _factor;
    }

    internal readonly struct SpeedProportionalSpinDecayLaw : ISpinDecayLaw
    {
        private readonly double _rate;

        public SpeedProportionalSpinDecayLaw(double ratePerMetre) => _rate = ratePerMetre;

        public bool IsPresent => true;

        public AeroInputs Reads => AeroInputs.None;

        public Vector3d SpinAcceleration(in Vector3d angularVelocity, in AeroConditions conditions) =>
            angularVelocity * (-_rate * conditions.Speed);

        public bool SpeedOnly => true;

        // SpinAcceleration's expression, the speed given as it is in the conditions.
        public Vector3d SpinAccelerationAtSpeed(in Vector3d angularVelocity, double speed) => angularVelocity * (-_rate * speed);
    }
}
