/**
 * The peer's (SPHinXsys's) elastic gate alone, in vacuum: the gate of
 * tests/2d_examples/test_2d_elastic_gate/elastic_gate.cpp with its geometry, offset,
 * clamp, material (E = 7.8 MPa, nu = 0.47, rho = 1100 kg/m^3), resolution (1.25 mm,
 * 4 particles across the 5 mm) and solid integration (Integration1stHalfPK2 with the
 * linear gradient correction, acoustic time step), without water or gravity. It starts
 * with the first bending mode's velocity profile (free-end amplitude about 1 mm, linear)
 * and writes the free end's position, so that its first bending period can be compared
 * with beam theory (scripts/peer/compare_elastic_gate.py).
 *
 * Units are the peer's: mm, ms, density 1 = 1000 kg/m^3, stress 1 = 1 kPa.
 * Output: output/Observer_Position.dat (time, then x and y of the observers: the free
 * end's mid-point, then the lower left corner the peer's elastic gate observes).
 */
#include "sphinxsys.h"
using namespace SPH;

// The elastic gate's geometry (elastic_gate.cpp), in mm.
Real DL = 500.0;
Real DH = 200.1;
Real Dam_L = 100.0;
Real Dam_H = 140.0;
Real Gate_width = 5.0;
Real Base_bottom_position = 79.0;
Real global_resolution = Gate_width / 2.0;
Real BW = global_resolution * 4.0;
Real dp_s = 0.5 * global_resolution;
Vec2d offset = Vec2d(0.0, Base_bottom_position - floor(Base_bottom_position / dp_s) * dp_s);
BoundingBoxd system_domain_bounds(Vec2d(-BW, -BW), Vec2d(DL + BW, DH + BW));
Vec2d GateP_lb(DL - Dam_L - Gate_width, 0.0);
Vec2d GateP_lt(DL - Dam_L - Gate_width, Dam_H + BW);
Vec2d GateP_rt(DL - Dam_L, Dam_H + BW);
Vec2d GateP_rb(DL - Dam_L, 0.0);
Vec2d ConstrainP_lb(DL - Dam_L - Gate_width, Base_bottom_position);
Vec2d ConstrainP_lt(DL - Dam_L - Gate_width, Dam_H + BW);
Vec2d ConstrainP_rt(DL - Dam_L, Dam_H + BW);
Vec2d ConstrainP_rb(DL - Dam_L, Base_bottom_position);
// The gate's material (elastic_gate.cpp).
Real rho0_s = 1.1;
Real poisson = 0.47;
Real Youngs_modulus = 7.8e3;
// The free length: from the offset gate's lower end to the clamp.
Real free_length = Base_bottom_position - offset[1];
StdVec<Vecd> observation_location = {Vecd(GateP_lb[0] + 0.5 * Gate_width, offset[1]), GateP_lb};
// First clamped-free bending mode, phi(s) = cosh ks - cos ks - sigma (sinh ks - sin ks),
// s from the clamp; phi = 2 at the free end.
Real kl = 1.8751040687;
Real sigma = (cosh(kl) + cos(kl)) / (sinh(kl) + sin(kl));
// Free-end speed at the start (mm/ms): about 1 mm of amplitude at the beam's omega (~0.078 /ms).
Real tip_speed = 0.08;

MultiPolygon createShape(const std::vector<Vecd> &corners)
{
    MultiPolygon multi_polygon;
    multi_polygon.addPolygon(corners, GeometricOps::add);
    return multi_polygon;
}

class FirstModeVelocity : public solid_dynamics::ElasticDynamicsInitialCondition
{
  public:
    explicit FirstModeVelocity(SPHBody &sph_body)
        : solid_dynamics::ElasticDynamicsInitialCondition(sph_body) {};

    void update(size_t index_i, Real dt)
    {
        Real s = (Base_bottom_position - pos_[index_i][1]) / free_length;
        if (s > 0.0)
        {
            Real phi = cosh(kl * s) - cos(kl * s) - sigma * (sinh(kl * s) - sin(kl * s));
            vel_[index_i][0] = 0.5 * tip_speed * phi;
        }
    };
};

int main(int ac, char *av[])
{
    Real end_time = 400.0;
    if (ac > 1)
        end_time = std::stod(av[1]);
    SPHSystem sph_system(system_domain_bounds, global_resolution);

    std::vector<Vecd> gate_corners{GateP_lb, GateP_lt, GateP_rt, GateP_rb, GateP_lb};
    SolidBody gate(sph_system, makeShared<MultiPolygonShape>(createShape(gate_corners), "Gate"));
    gate.defineAdaptationRatios(1.15, 2.0);
    gate.defineMatterMaterial<SaintVenantKirchhoffSolid>(rho0_s, Youngs_modulus, poisson);
    gate.generateParticles<BaseParticles, Lattice>();

    ObserverBody gate_observer(sph_system, "Observer");
    gate_observer.defineAdaptationRatios(1.15, 2.0);
    gate_observer.generateParticles<ObserverParticles>(observation_location);

    InnerRelation gate_inner(gate);
    ContactRelation gate_observer_contact(gate_observer, {&gate});

    SimpleDynamics<OffsetInitialPosition> gate_offset_position(gate, offset);
    InteractionWithUpdate<LinearGradientCorrectionMatrixInner> gate_corrected_configuration(gate_inner);
    Dynamics1Level<solid_dynamics::Integration1stHalfPK2> gate_stress_relaxation_first_half(gate_inner);
    Dynamics1Level<solid_dynamics::Integration2ndHalf> gate_stress_relaxation_second_half(gate_inner);
    ReduceDynamics<solid_dynamics::AcousticTimeStep> gate_computing_time_step_size(gate);
    std::vector<Vecd> clamp_corners{ConstrainP_lb, ConstrainP_lt, ConstrainP_rt, ConstrainP_rb, ConstrainP_lb};
    BodyRegionByParticle gate_constraint_part(gate, makeShared<MultiPolygonShape>(createShape(clamp_corners)));
    SimpleDynamics<FixBodyPartConstraint> gate_constraint(gate_constraint_part);
    SimpleDynamics<FirstModeVelocity> gate_initial_velocity(gate);
    ObservedQuantityRecording<Vecd> write_tip_position("Position", gate_observer_contact);

    gate_offset_position.exec();
    sph_system.initializeSystemCellLinkedLists();
    sph_system.initializeSystemConfigurations();
    gate_corrected_configuration.exec();
    gate_initial_velocity.exec();

    Real &physical_time = *sph_system.getSystemVariableDataByName<Real>("PhysicalTime");
    Real output_interval = 0.1;
    Real dt = 0.0;
    write_tip_position.writeToFile(0);
    size_t steps = 0;
    while (physical_time < end_time)
    {
        Real integration_time = 0.0;
        while (integration_time < output_interval)
        {
            gate_stress_relaxation_first_half.exec(dt);
            gate_constraint.exec();
            gate_stress_relaxation_second_half.exec(dt);
            dt = gate_computing_time_step_size.exec();
            integration_time += dt;
            physical_time += dt;
            steps++;
        }
        write_tip_position.writeToFile(steps);
    }
    std::cout << "steps " << steps << ", last dt " << dt << " ms\n";
    return 0;
}
