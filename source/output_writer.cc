#include <deal.II/numerics/data_out.h>

#include <thinlayer/elasticity.h>
#include <thinlayer/output_writer.h>
#include <thinlayer/results_directory.h>
#include <thinlayer/text_format.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>

namespace thinlayer
{
  namespace
  {
    /// Throw a WriteError naming the file @p name if @p stream failed.
    void
    check_written(const std::ostream &stream, const std::string &name)
    {
      if (!stream)
        throw WriteError(
          "cannot write " + name + ": " +
          (errno != 0 ? std::strerror(errno) : "the stream failed"));
    }
  } // namespace


  OutputWriter::OutputWriter(const OutputParameters &parameters,
                             const std::string      &directory)
    : directory(directory)
    , vtu_subdivisions(parameters.vtu_subdivisions)
  {
    errno = 0;
    history.open(directory + "/history.csv");
    history << "step,attempt,load_factor,load,displacement,displacement_min,"
               "displacement_max,iterations,converged,accepted,"
               "max_yield_ratio,plastic_points,cut_backs,factorisations,"
               "stiffness_ratio,growth_ratio,non_finite\n"
            << std::flush;
    check_written(history, "history.csv");
  }


  void
  OutputWriter::write_history_row(const HistoryRow &row)
  {
    // A value that is not a finite number (a yield ratio where no
    // material can yield, a diverged step) as empty.
    const auto number = text_format::csv_number;
    errno             = 0;
    history << row.step << ',' << row.attempt << ',' << number(row.load_factor)
            << ',' << number(row.load) << ',' << number(row.displacement.mean)
            << ',' << number(row.displacement.min) << ','
            << number(row.displacement.max) << ',' << row.result.iterations
            << ',' << (row.result.converged ? 1 : 0) << ','
            << (row.accepted ? 1 : 0) << ','
            << number(row.result.max_yield_ratio) << ','
            << row.result.plastic_points << ',' << row.result.cut_backs << ','
            << row.result.factorisations << ',' << number(row.stiffness_ratio)
            << ',' << number(row.result.growth_ratio) << ','
            << (row.result.non_finite ? 1 : 0) << '\n'
            << std::flush;
    check_written(history, "history.csv");
  }


  namespace
  {
    /**
     * Cell averages of the point fields: the stresses live at Gauss points
     * with their plastic history, not at nodes. At every station: the
     * stress components (the four that plane strain has; all six for
     * Fourier, where the shear stresses with theta come from the higher
     * harmonics), the equivalent stress, the equivalent plastic strain and
     * the yield ratio. The yield ratio is the cell's maximum, to show where
     * drift into illegal stress space is.
     */
    struct CellFields
    {
      template <int dim>
      explicit CellFields(const Analysis<dim> &analysis);

      /// (i, j) of the stress components written: plane strain the first
      /// four (xx, yy, zz, xy), Fourier all six (rr, zz, tt, rz, rt, zt).
      static constexpr unsigned int components[6][2] =
        {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
      unsigned int n_components;
      /// Per station, per component.
      std::vector<std::vector<Vector<double>>> stress;
      std::vector<Vector<double>> equivalent, plastic_strain, yield_ratio;
      Vector<double>              material;
    };


    template <int dim>
    CellFields::CellFields(const Analysis<dim> &analysis)
    {
      const auto        &tria = analysis.get_dof_handler().get_triangulation();
      const unsigned int n_q  = analysis.n_quadrature_points();
      const unsigned int n_cells = tria.n_active_cells();
      const unsigned int n_s     = analysis.get_kinematics().n_stations();
      n_components = analysis.get_kinematics().is_fourier() ? 6 : 4;
      stress.assign(n_s,
                    std::vector<Vector<double>>(n_components,
                                                Vector<double>(n_cells)));
      equivalent.assign(n_s, Vector<double>(n_cells));
      plastic_strain.assign(n_s, Vector<double>(n_cells));
      yield_ratio.assign(n_s, Vector<double>(n_cells));
      material.reinit(n_cells);
      for (const auto &cell : tria.active_cell_iterators())
        {
          const unsigned int c   = cell->active_cell_index();
          const MaterialLaw &law = analysis.material_law(c);
          for (unsigned int s = 0; s < n_s; ++s)
            {
              yield_ratio[s][c] = law.can_yield()
                                    ? std::numeric_limits<double>::lowest()
                                    : std::numeric_limits<double>::quiet_NaN();
              for (unsigned int q = 0; q < n_q; ++q)
                {
                  const PointState &state = analysis.point_state(c, q, s);
                  for (unsigned int k = 0; k < n_components; ++k)
                    stress[s][k][c] +=
                      state.stress[components[k][0]][components[k][1]] / n_q;
                  equivalent[s][c] += equivalent_stress(state.stress) / n_q;
                  // Equivalent plastic strain sqrt(2/3 e:e).
                  plastic_strain[s][c] +=
                    std::sqrt(2. / 3. *
                              (state.plastic_strain * state.plastic_strain)) /
                    n_q;
                  if (law.can_yield())
                    yield_ratio[s][c] = std::max(yield_ratio[s][c],
                                                 law.yield_ratio(state.stress));
                }
            }
          material[c] = cell->material_id();
        }
    }
  } // namespace


  template <int dim>
  void
  OutputWriter::write_fields(const unsigned int   step,
                             const double         load_factor,
                             const Analysis<dim> &analysis,
                             const double         theta)
  {
    const auto                    &dof_handler = analysis.get_dof_handler();
    const Kinematics              &kinematics  = analysis.get_kinematics();
    const bool                     fourier     = kinematics.is_fourier();
    const CellFields               fields(analysis);
    const std::vector<std::string> names =
      fourier ? std::vector<std::string>{"stress_rr",
                                         "stress_zz",
                                         "stress_tt",
                                         "stress_rz",
                                         "stress_rt",
                                         "stress_zt"}
              : std::vector<std::string>{"stress_xx",
                                         "stress_yy",
                                         "stress_zz",
                                         "stress_xy"};

    DataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    // In-plane displacement as a vector; u_theta (Fourier) as a scalar. At
    // the monitored angle, which for Fourier is where the field is cut.
    const Vector<double>     u = analysis.displacement_at(theta);
    std::vector<std::string> displacement_names(dim, "displacement");
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim,
                     DataComponentInterpretation::component_is_part_of_vector);
    if (fourier)
      {
        displacement_names.push_back("displacement_theta");
        interpretation.push_back(
          DataComponentInterpretation::component_is_scalar);
      }
    data_out.add_data_vector(u,
                             displacement_names,
                             DataOut<dim>::type_dof_data,
                             interpretation);
    for (unsigned int s = 0; s < kinematics.n_stations(); ++s)
      {
        // Fourier fields carry their station's angle in degrees.
        const std::string suffix =
          fourier ? "_" + std::to_string(static_cast<int>(std::round(
                            kinematics.station_angle(s) * 180 / numbers::PI)))
                  : std::string();
        for (unsigned int k = 0; k < fields.n_components; ++k)
          data_out.add_data_vector(fields.stress[s][k], names[k] + suffix);
        data_out.add_data_vector(fields.equivalent[s],
                                 "equivalent_stress" + suffix);
        data_out.add_data_vector(fields.plastic_strain[s],
                                 "plastic_strain" + suffix);
        data_out.add_data_vector(fields.yield_ratio[s], "yield_ratio" + suffix);
      }
    data_out.add_data_vector(fields.material, "material_id");
    data_out.build_patches(analysis.get_mapping(),
                           vtu_subdivisions,
                           DataOut<dim>::curved_inner_cells);

    std::ostringstream name;
    name << "fields-" << std::setw(4) << std::setfill('0') << step << ".vtu";
    std::ostringstream vtu;
    data_out.write_vtu(vtu);
    write_file(name.str(), vtu.str());

    pvd_records.emplace_back(load_factor, name.str());
    std::ostringstream pvd;
    DataOutBase::write_pvd_record(pvd, pvd_records);
    write_file("fields.pvd", pvd.str());
  }


  template <int dim>
  void
  OutputWriter::write_displacements(const Analysis<dim> &analysis,
                                    const double         theta) const
  {
    const auto          &dof_handler = analysis.get_dof_handler();
    const bool           fourier     = analysis.get_kinematics().is_fourier();
    const Vector<double> u           = analysis.displacement_at(theta);
    const Vector<double> du          = analysis.displacement_at(theta, true);
    // The Cartesian components in the cut at theta: x = u_r cos(theta) -
    // u_theta sin(theta) for Fourier, and y along the axis.
    const auto x_component = [&](const Vector<double>         &v,
                                 const types::global_dof_index r,
                                 const types::global_dof_index t) {
      return fourier ? v[r] * std::cos(theta) - v[t] * std::sin(theta) : v[r];
    };
    std::vector<bool>  written(dof_handler.get_triangulation().n_vertices());
    std::ostringstream csv;
    csv << std::setprecision(10) << "x,y,u_x,u_y,du_x,du_y\n";
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (!written[cell->vertex_index(v)])
          {
            written[cell->vertex_index(v)] = true;
            const auto r                   = cell->vertex_dof_index(v, 0);
            const auto z                   = cell->vertex_dof_index(v, 1);
            const auto t = fourier ? cell->vertex_dof_index(v, 2) : r;
            csv << cell->vertex(v)[0] << ',' << cell->vertex(v)[1] << ','
                << x_component(u, r, t) << ',' << u[z] << ','
                << x_component(du, r, t) << ',' << du[z] << '\n';
          }
    write_file("displacements.csv", csv.str());
  }


  void
  OutputWriter::write_file(const std::string &name,
                           const std::string &content) const
  {
    // Write beside, then rename: a reader never sees half a file.
    const std::string path = directory + "/" + name;
    errno                  = 0;
    {
      std::ofstream out(path + ".partial");
      out << content;
      out.close();
      check_written(out, name);
    }
    std::error_code error;
    std::filesystem::rename(path + ".partial", path, error);
    if (error)
      throw WriteError("cannot write " + name + ": " + error.message());
  }


  const std::string &
  OutputWriter::get_directory() const
  {
    return directory;
  }


  template void
  OutputWriter::write_displacements(const Analysis<2> &, const double) const;

  template void
  OutputWriter::write_fields(const unsigned int,
                             const double,
                             const Analysis<2> &,
                             const double);
} // namespace thinlayer
